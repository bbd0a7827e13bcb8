// A tile's regular grid of the pyramid's exact surface, with a ring of the neighbours' samples
// around it (the apron) so that a vertex's normal on the tile's edge is the one its neighbour
// computes for the same vertex: no seam in the lighting between tiles.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"
#include "surface/pyramid_surface.hpp"

namespace globe::publish {

struct TileGrid {
  geo::TileId tile;
  uint32_t side = 0;
  std::vector<double> heightsMeters;  // side², rows from the north, columns from the west
  std::vector<double> apronMeters;    // (side + 2)²: the grid and the ring around it

  double apronAt(int row, int column) const {  // row, column in [-1, side]
    return apronMeters[static_cast<size_t>(row + 1) * (side + 2) + static_cast<size_t>(column + 1)];
  }
};

// The surface at the tile's side×side grid (the level's BlockGrid for that many vertices), from
// the finest tile of level <= maxLevel under each sample.
Result<TileGrid> sampleTileGrid(surface::PyramidSurface& surface, const geo::TileId& tile, uint32_t side,
                                uint32_t maxLevel);

// The grid's samples in ECEF metres (rows from the north): the same bits for a vertex shared with
// a neighbour, whichever tile computes it.
std::vector<std::array<double, 3>> gridPositionsEcefMeters(const TileGrid& grid,
                                                           const geo::Ellipsoid& ellipsoid);

// Unit normals (ECEF) of the surface at grid sample (row, column), by central differences over
// the apron; the ellipsoid's normal where they degenerate (at a pole).
std::array<float, 3> gridNormal(const TileGrid& grid, const geo::Ellipsoid& ellipsoid, int row,
                                int column);

}  // namespace globe::publish
