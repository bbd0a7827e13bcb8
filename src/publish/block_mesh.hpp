// A grid of heights over a tile as a quantized-mesh-1.0 tile: either the whole G×G grid, split
// along the renderer's diagonals (terrain/tile_mesh.hpp) so that a client interpolating it draws
// the surface globe draws, or a TIN simplified from it. The tile's TMS name is the block's: both
// tilings are the same 2×1 geographic quadtree (only the rows count from the south).
#pragma once

#include <cstdint>
#include <vector>

#include "formats/quantized_mesh.hpp"
#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"
#include "publish/tin_simplifier.hpp"

namespace globe::publish {

struct BlockMesh {
  formats::QuantizedMesh mesh;
  formats::QuantizedMeshCulling culling;
};

// heightsMeters: G×G (G >= 2) rows from the north, columns from the west, at the tile's grid
// of G vertices per side (the level's BlockGrid for G vertices).
BlockMesh quantizedMeshOfGrid(const geo::TileId& tile, uint32_t verticesPerSide,
                              const std::vector<double>& heightsMeters,
                              const geo::Ellipsoid& ellipsoid);

// The whole G×G grid as a TIN, split along the renderer's diagonals (north-west to south-east),
// counter-clockwise seen from above.
GridTin wholeGridTin(uint32_t verticesPerSide);

// The same grid as the TIN simplifyGrid made of it: its vertices, triangles and edge lists (each
// side's vertices in order, from the south or the west). The culling volumes bound the whole grid.
BlockMesh quantizedMeshOfTin(const geo::TileId& tile, uint32_t verticesPerSide,
                             const std::vector<double>& heightsMeters, const GridTin& tin,
                             const geo::Ellipsoid& ellipsoid);

}  // namespace globe::publish
