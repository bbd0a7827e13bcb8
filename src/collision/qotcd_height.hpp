// The terrain height H of the paper's Intersecting Point in its tile: the vertex height on a
// vertex, the higher of the two neighbours on a row or column, the highest of four in a quad.
#pragma once

#include "collision/terrain_array.hpp"

namespace globe::collision {

enum class HeightCase {
  None,         // no height read (no tile, invalid input)
  Vertex,       // on a vertex (within the grid epsilon), or on a pole row (its highest vertex)
  RowOrColumn,  // on a row or column line between two vertices: the higher of the two
  Quad,         // inside a quad: the highest of its four vertices
  TileMaximum,  // early-out: the block was not read; the height is the tile's maximum
};

struct TileHeight {
  double heightMeters = 0.0;
  HeightCase heightCase = HeightCase::None;
};

// H per the paper for a point (canonical longitude) contained in the tile; no-data counts as
// 0 m. On a row at +-90 deg (all its vertices are the pole) H is the highest vertex of that row.
// A tile without a readable block (hasReadableBlock) gives {0, None}.
TileHeight qotcdTileHeight(const ArrayTile& tile, double longitudeRadians, double latitudeRadians);

}  // namespace globe::collision
