// A grid of heights over a tile as a quantized-mesh-1.0 tile: the G×G grid as the TIN, split
// along the renderer's diagonals (terrain/tile_mesh.hpp), so that a client interpolating the TIN
// draws the surface globe draws. The tile's TMS name is the block's: both tilings are the same
// 2×1 geographic quadtree (only the rows count from the south).
#pragma once

#include <cstdint>
#include <vector>

#include "formats/quantized_mesh.hpp"
#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"

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

}  // namespace globe::publish
