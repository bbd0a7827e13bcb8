// Where a point lies in a tile's vertex grid: on a vertex, on a row or column line, inside a
// quad, or on a pole row; with the epsilon that decides "on".
#pragma once

#include <cstdint>

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

// For a point (canonical longitude, see tile_containment.hpp) contained in the tile. Points
// slightly outside (by rounding) are clamped onto the grid; the block is never read outside.
GridLocation locateInGrid(const ArrayTile& tile, double longitudeRadians, double latitudeRadians);

}  // namespace globe::collision
