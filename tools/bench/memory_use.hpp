// Memory each collision method holds per tile beyond the tile's height block.
#pragma once

#include "collision/sphere_tree.hpp"
#include "terrain/rendering_tile_array.hpp"

namespace globe::bench {

struct MemoryUse {
  double sphereTreeBytesPerTile = 0;    // the trees (nodes, vertices, roots); no array needed
  double qotcdLinearBytesPerTile = 0;   // the array's tile record (bounds, id, block, maximum)
  double qotcdIndexedBytesPerTile = 0;  // the record and the array's tile index
  double exactSurfaceBytesPerTile = 0;  // as indexed: the vertices are computed per query
};

MemoryUse memoryUse(const terrain::RenderingTileArray& array,
                    const collision::SphereTreeSet& trees);

}  // namespace globe::bench
