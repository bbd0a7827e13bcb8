// A fingerprint of each edge of a block as drawn: two tiles of one level draw their shared edge
// at the same places exactly when its vertices' heights are equal (the positions come from the
// tile grid's degrees and the height alone, tile_mesh.hpp), and only then do their meshes meet
// without a crack and without a skirt. Blocks from one pyramid level agree; a block made from its
// parent's surface (upsampled_block.hpp) or morphing towards it does not agree with a neighbour
// read from the pyramid, so the renderer compares these and hangs a skirt where they differ.
#pragma once

#include <array>
#include <cstdint>

#include "terrain/height_block.hpp"

namespace globe::terrain {

// Per TileEdge (North, South, West, East): a 64-bit hash of the edge's vertex heights
// (surfaceHeightMetersAt, -0 taken as 0), North and South west→east, West and East north→south,
// so a tile's South hash equals its southern neighbour's North hash when they draw the same
// edge. All zero for a block that is not a complete valid grid.
using EdgeHeightHashes = std::array<uint64_t, 4>;

EdgeHeightHashes edgeHeightHashes(const HeightBlock& block);

}  // namespace globe::terrain
