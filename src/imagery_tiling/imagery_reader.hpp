// Draws one input into 256×256 longitude/latitude tiles. One reader per worker thread and input:
// GDAL datasets are not thread-safe. Rasters are warped through GDAL's transformer (exact on a
// 17×17 grid of each tile, interpolated between where that stays within 1/8 pixel, exact per
// pixel elsewhere) and sampled bilinearly with premultiplied alpha; TMS trees give their own
// tiles, or the ancestor's pixels upsampled below their finest level.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "core/result.hpp"
#include "formats/image_io.hpp"
#include "geo/tile_id.hpp"
#include "imagery_tiling/imagery_input.hpp"

namespace globe::imagery_tiling {

class ImageryReader {
 public:
  virtual ~ImageryReader() = default;
  static Result<std::unique_ptr<ImageryReader>> open(const ImageryInput& input);

  // Draws the input into `tile` (which the caller made transparent); false when it covers no
  // pixel of it.
  virtual Result<bool> render(const geo::TileId& tile, formats::ImageRgba& out) = 0;
  // A TMS tree's own encoded tile (JPEG or PNG, 256×256, checked by decoding) at this level, to be
  // re-packed as is; nullopt when it has none. Rasters have none.
  virtual Result<std::optional<std::vector<std::byte>>> ownTile(const geo::TileId& tile);
};

// A tile's west/north edges and width in degrees.
struct TileFrameDegrees {
  double west = 0, north = 0, size = 0;
};
TileFrameDegrees tileFrameDegrees(const geo::TileId& tile);

}  // namespace globe::imagery_tiling
