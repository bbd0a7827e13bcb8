// An imagery layer as a tile source: its tiles read from the layer's packs (one read each) and
// decoded to RGBA8 on the loader's worker thread, so the main thread only uploads.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "formats/image_io.hpp"
#include "streaming/imagery_store.hpp"
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
  explicit ImagerySource(ImageryStore& store) : store_(store) {}

  // A tile whose decoded size is not the layer's tile size is an error, not a picture drawn
  // at the wrong scale.
  Result<std::optional<formats::ImageRgba>> load(const geo::TileId& tile) override;
  std::string location(const geo::TileId& tile) const override;
  std::vector<std::string> takeNewSourceErrors() override { return store_.takeNewPackErrors(); }
  void forgetSourceFailures() override { store_.forgetFailedPacks(); }

 private:
  ImageryStore& store_;
};

extern template class TileCache<formats::ImageRgba>;
extern template class PayloadLoader<formats::ImageRgba>;

}  // namespace globe::streaming
