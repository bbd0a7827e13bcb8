// A block of Web-Mercator elevation pixels (Terrarium, Terrain-RGB) as the TIN of their bilinear
// surface: vertices on the pixel centres' rows and columns within the block (and where they cross
// its edges), so the drawn triangles bend where the pixels do, cliffs included, where a
// geographic grid's rows fall between the pixels' and cut the corners. A pixel square whose
// bilinear twist (h00 + h11 − h01 − h10) two triangles would miss by more than the tolerance is
// cut into k×k smaller squares: the bilinear surface is linear along every row and column, so
// the extra vertices lie on the neighbours' edges (no cracks).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "geo/globe_rectangle.hpp"
#include "terrain/tin_tile.hpp"

namespace globe::services {

// The pixels around a block: heights of global pixels (column, row from the north, of a world
// `worldPixels` wide at the zoom) firstColumn.. and firstRow.., row-major; the caller wraps
// columns across ±180° and clamps rows at the poles.
struct PixelWindow {
  int64_t firstColumn = 0, firstRow = 0;
  int64_t columns = 0, rows = 0;
  double worldPixels = 256;
  std::vector<double> heightMeters;
  double at(int64_t column, int64_t row) const {
    return heightMeters[static_cast<size_t>((row - firstRow) * columns + (column - firstColumn))];
  }
};

// The global pixel coordinates (pixel centres at whole numbers) of a longitude and latitude.
double pixelColumnOf(double longitudeRadians, double worldPixels);
double pixelRowOf(double latitudeRadians, double worldPixels);

// The window of pixels the block's bilinear surface reads (what buildPixelTin needs).
struct PixelRange {
  int64_t firstColumn = 0, lastColumn = 0, firstRow = 0, lastRow = 0;
};
PixelRange pixelRangeOf(const geo::GlobeRectangle& block, double worldPixels);

// The block's TIN, every triangle within `toleranceMeters` of the pixels' bilinear surface
// (where more than kMaxVertices would be needed, a wider tolerance). Every window height must be
// finite. Errors name `name`.
inline constexpr size_t kMaxPixelTinVertices = size_t{1} << 18;
Result<std::shared_ptr<const terrain::TinTile>> buildPixelTin(const geo::GlobeRectangle& block,
                                                              const PixelWindow& pixels,
                                                              double toleranceMeters,
                                                              const std::string& name);

}  // namespace globe::services
