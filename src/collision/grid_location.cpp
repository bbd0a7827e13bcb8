// Grid coordinates of a point in a tile and the snapping of points onto vertices and lines.
#include "collision/grid_location.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "collision/terrain_array.hpp"

namespace globe::collision {
namespace {

struct Axis {
  double coordinate;
  uint32_t cell;
  bool snapped;
  uint32_t line;
};

// coordinate: position in cells from the first line; spanRadians: the tile's extent.
Axis locateOnAxis(double coordinate, double cells, double spanRadians) {
  Axis axis{};
  axis.coordinate = std::isfinite(coordinate) ? std::clamp(coordinate, 0.0, cells) : 0.0;
  const double epsilon = std::max(kGridEpsilonCells, kGridEpsilonRadians * cells / spanRadians);
  const double nearest = std::nearbyint(axis.coordinate);
  axis.snapped = std::abs(axis.coordinate - nearest) <= epsilon;
  axis.line = static_cast<uint32_t>(nearest);
  axis.cell = std::min(static_cast<uint32_t>(std::floor(axis.coordinate)),
                       static_cast<uint32_t>(cells) - 1);
  return axis;
}

}  // namespace

GridLocation locateInGrid(const ArrayTile& tile, double longitudeRadians, double latitudeRadians) {
  const uint32_t cells = tile.block->verticesPerSide - 1;
  const double cellCount = static_cast<double>(cells);
  const double width = tile.eastRadians - tile.westRadians;
  const double height = tile.northRadians - tile.southRadians;
  const double longitude = longitudeInTile(tile, longitudeRadians);
  const Axis column =
      locateOnAxis((longitude - tile.westRadians) / width * cellCount, cellCount, width);
  const Axis row =
      locateOnAxis((tile.northRadians - latitudeRadians) / height * cellCount, cellCount, height);

  GridLocation location;
  location.column = column.coordinate;
  location.row = row.coordinate;
  location.quadColumn = column.cell;
  location.quadRow = row.cell;
  location.onColumn = column.snapped;
  location.onRow = row.snapped;
  location.snappedColumn = column.line;
  location.snappedRow = row.line;
  constexpr double kHalfPi = std::numbers::pi / 2.0;
  if (row.snapped && row.line == 0 && tile.northRadians >= kHalfPi) {
    location.atPole = true;
    location.poleRow = 0;
  } else if (row.snapped && row.line == cells && tile.southRadians <= -kHalfPi) {
    location.atPole = true;
    location.poleRow = cells;
  }
  return location;
}

}  // namespace globe::collision
