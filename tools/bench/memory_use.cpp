// Per-tile memory of the methods, from the structures' own sizes.
#include "tools/bench/memory_use.hpp"

namespace globe::bench {

MemoryUse memoryUse(const terrain::RenderingTileArray& array,
                    const collision::SphereTreeSet& trees) {
  MemoryUse use;
  const auto tiles = static_cast<double>(array.tiles().size());
  if (tiles == 0) return use;
  const double record = sizeof(terrain::ArrayTile);
  use.sphereTreeBytesPerTile = static_cast<double>(trees.memoryBytes()) / tiles;
  use.qotcdLinearBytesPerTile = record;
  use.qotcdIndexedBytesPerTile = record + static_cast<double>(array.indexMemoryBytes()) / tiles;
  use.exactSurfaceBytesPerTile = use.qotcdIndexedBytesPerTile;
  return use;
}

}  // namespace globe::bench
