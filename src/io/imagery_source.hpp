// An imagery layer as a tile source: its tiles read from the layer's packs (one read each) and
// decoded to RGBA8 on the loader's worker thread, so the main thread only uploads.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/image_io.hpp"
#include "io/imagery_store.hpp"
#include "io/tile_cache.hpp"
#include "io/tile_loader.hpp"
#include "io/tile_source.hpp"

namespace globe::io {

template <>
struct PayloadBytes<ImageRgba> {
  static size_t of(const ImageRgba& image) { return image.pixels.size(); }
};

using ImageryCache = TileCache<ImageRgba>;
using ImageryLoader = PayloadLoader<ImageRgba>;

class ImagerySource final : public TileSource<ImageRgba> {
 public:
  explicit ImagerySource(ImageryStore& store) : store_(store) {}

  // A tile whose decoded size is not the layer's tile size is an error, not a picture drawn
  // at the wrong scale.
  Result<std::optional<ImageRgba>> load(const geo::TileId& tile) override;
  std::string location(const geo::TileId& tile) const override;
  std::vector<std::string> takeNewSourceErrors() override { return store_.takeNewPackErrors(); }
  void forgetSourceFailures() override { store_.forgetFailedPacks(); }

 private:
  ImageryStore& store_;
};

extern template class TileCache<ImageRgba>;
extern template class PayloadLoader<ImageRgba>;

}  // namespace globe::io
