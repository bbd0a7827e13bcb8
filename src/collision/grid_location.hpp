// Where a point lies in a tile's vertex grid: on a vertex, on a row or column line, inside a
// quad, or on a pole row; with the epsilon that decides "on".
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "collision/terrain_array.hpp"

namespace globe::collision {

// A point counts as on a grid line when it is within this fraction of a cell of it...
inline constexpr double kGridEpsilonCells = 1e-9;
// ...or within this angle (~2.5e-8 m on the ground, ~9 ulps of pi), whichever is larger, so that
// rounding of the longitude/latitude is absorbed even in the cells of very deep levels.
inline constexpr double kGridEpsilonRadians = 4e-15;

struct GridLocation {
  // Continuous grid coordinates clamped to [0, N-1]: column grows east, row grows south.
  double column = 0.0;
  double row = 0.0;
  // The quad holding the point: its north-west vertex, in [0, N-2].
  uint32_t quadColumn = 0;
  uint32_t quadRow = 0;
  // On a column line (constant longitude) / row line (constant latitude), and which one.
  bool onColumn = false;
  bool onRow = false;
  uint32_t snappedColumn = 0;
  uint32_t snappedRow = 0;
  // On a row at latitude +-90 deg: every vertex of that row is the pole itself.
  bool atPole = false;
  uint32_t poleRow = 0;
};

namespace grid_detail {

struct Axis {
  double coordinate;
  uint32_t cell;
  bool snapped;
  uint32_t line;
};

// coordinate: position in cells from the first line; cellsPerRadian: cells / the tile's extent.
inline Axis locateOnAxis(double coordinate, double cells, double cellsPerRadian) {
  Axis axis{};
  axis.coordinate = std::isfinite(coordinate) ? std::clamp(coordinate, 0.0, cells) : 0.0;
  const double epsilon = std::max(kGridEpsilonCells, kGridEpsilonRadians * cellsPerRadian);
  // The coordinate is in [0, cells]: truncation is floor, and +0.5 then truncation the nearest
  // line (a tie is never within epsilon of a line) without a call into libm.
  const auto nearest = static_cast<uint32_t>(axis.coordinate + 0.5);
  axis.snapped = std::abs(axis.coordinate - static_cast<double>(nearest)) <= epsilon;
  axis.line = nearest;
  axis.cell = std::min(static_cast<uint32_t>(axis.coordinate), static_cast<uint32_t>(cells) - 1);
  return axis;
}

}  // namespace grid_detail

// For a point (canonical longitude, see tile_containment.hpp) contained in the tile. Points
// slightly outside (by rounding) are clamped onto the grid; the block is never read outside.
// Inline (with its helper) because every QOTCD and exact-surface query runs it: a call and the
// struct through memory cost as much as the arithmetic.
inline GridLocation locateInGrid(const ArrayTile& tile, double longitudeRadians,
                                 double latitudeRadians) {
  using grid_detail::Axis;
  using grid_detail::locateOnAxis;
  const uint32_t cells = tile.block->verticesPerSide - 1;
  const double cellCount = static_cast<double>(cells);
  // One division per axis (a query's costliest instructions after the conversion's).
  const double columnsPerRadian = cellCount / (tile.eastRadians - tile.westRadians);
  const double rowsPerRadian = cellCount / (tile.northRadians - tile.southRadians);
  const double longitude = longitudeInTile(tile, longitudeRadians);
  const Axis column =
      locateOnAxis((longitude - tile.westRadians) * columnsPerRadian, cellCount, columnsPerRadian);
  const Axis row =
      locateOnAxis((tile.northRadians - latitudeRadians) * rowsPerRadian, cellCount, rowsPerRadian);

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
