// Row-sliver allowance and chord-sag bound of a tile's drawn surface.
#include "tests/collision/surface_bounds.hpp"

#include <algorithm>
#include <cmath>

#include "collision/grid_location.hpp"

namespace globe::collision::testing {

double rowSliverAllowanceMeters(const ArrayTile& tile, double latitudeRadians,
                                const geo::Ellipsoid& ellipsoid) {
  const uint32_t cells = tile.block->verticesPerSide - 1;
  const double a = ellipsoid.semiMajorAxisMeters;
  const double cellLongitude = (tile.eastRadians - tile.westRadians) / cells;
  const double cellLatitude = (tile.northRadians - tile.southRadians) / cells;
  const double bulge = a * std::abs(std::sin(latitudeRadians) * std::cos(latitudeRadians)) *
                       cellLongitude * cellLongitude / 8.0;
  const GridLocation at = locateInGrid(tile, tile.westRadians, latitudeRadians);
  double steepest = 0.0;
  for (uint32_t row = at.quadRow > 0 ? at.quadRow - 1 : 0;
       row <= std::min(at.quadRow + 1, cells - 1); ++row) {
    for (uint32_t column = 0; column <= cells; ++column) {
      steepest = std::max(steepest, std::abs(tile.block->surfaceHeightMetersAt(row + 1, column) -
                                             tile.block->surfaceHeightMetersAt(row, column)));
    }
  }
  return 1e-6 + 1.1 * bulge * steepest / (a * cellLatitude);
}

double chordSagBoundMeters(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid) {
  const double cells = tile.block->verticesPerSide - 1.0;
  const double cellLongitude = (tile.eastRadians - tile.westRadians) / cells;
  const double cellLatitude = (tile.northRadians - tile.southRadians) / cells;
  const double spread = std::hypot(cellLongitude, cellLatitude);
  const double a = ellipsoid.semiMajorAxisMeters;
  const double b = ellipsoid.semiMinorAxisMeters;
  return 1e-6 + a * spread * spread / 2.0 + (a - b) * spread;
}

}  // namespace globe::collision::testing
