// An imagery layer as a tile source: its tiles read (from packs, or a service) and decoded to
// RGBA8 on the loader's worker thread, so the main thread only uploads.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "formats/image_io.hpp"
#include "streaming/imagery_tiles.hpp"
#include "streaming/tile_cache.hpp"
#include "streaming/tile_loader.hpp"
#include "streaming/tile_source.hpp"

namespace globe::streaming {

template <>
struct PayloadBytes<formats::ImageRgba> {
  static size_t of(const formats::ImageRgba& image) { return image.pixels.size(); }
};

using ImageryCache = TileCache<formats::ImageRgba>;
using ImageryLoader = PayloadLoader<formats::ImageRgba>;

class ImagerySource final : public TileSource<formats::ImageRgba> {
 public:
  explicit ImagerySource(ImageryTiles& tiles) : tiles_(tiles) {}

  Result<std::optional<formats::ImageRgba>> load(const geo::TileId& tile) override;
  std::string location(const geo::TileId& tile) const override;
  std::vector<std::string> takeNewSourceErrors() override { return tiles_.takeNewSourceErrors(); }
  void forgetSourceFailures() override { tiles_.forgetSourceFailures(); }

 private:
  ImageryTiles& tiles_;
};

extern template class TileCache<formats::ImageRgba>;
extern template class PayloadLoader<formats::ImageRgba>;

}  // namespace globe::streaming
