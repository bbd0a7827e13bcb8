#include "streaming/imagery_source.hpp"

namespace globe::streaming {

template class TileCache<formats::ImageRgba>;
template class PayloadLoader<formats::ImageRgba>;

Result<std::optional<formats::ImageRgba>> ImagerySource::load(const geo::TileId& tile) {
  return tiles_.loadImage(tile);
}

std::string ImagerySource::location(const geo::TileId& tile) const {
  return tiles_.tileLocation(tile);
}

}  // namespace globe::streaming
