#include "streaming/imagery_source.hpp"

namespace globe::streaming {

template class TileCache<formats::ImageRgba>;
template class PayloadLoader<formats::ImageRgba>;

Result<std::optional<formats::ImageRgba>> ImagerySource::load(const geo::TileId& tile) {
  auto encoded = store_.loadEncoded(tile);
  if (!encoded) return Error{encoded.error()};
  if (!*encoded) return std::optional<formats::ImageRgba>{};
  auto image = formats::decodeImageRgba(**encoded, location(tile));
  if (!image) return Error{image.error()};
  const auto size = static_cast<int>(store_.manifest().tileSizePixels);
  if (image->widthPixels != size || image->heightPixels != size) {
    return makeError(location(tile) + ": " + geo::tileName(tile) + " is " +
                     std::to_string(image->widthPixels) + "x" +
                     std::to_string(image->heightPixels) + " pixels, the layer's tiles are " +
                     std::to_string(size) + "x" + std::to_string(size));
  }
  return std::optional<formats::ImageRgba>{std::move(*image)};
}

std::string ImagerySource::location(const geo::TileId& tile) const {
  return store_.packFileOf(tile);
}

}  // namespace globe::streaming
