// The resident height blocks: the tile cache (streaming/tile_cache.hpp) over height blocks.
#pragma once

#include <cstdint>

#include "streaming/tile_cache.hpp"
#include "terrain/height_block.hpp"

namespace globe::streaming {

template <>
struct PayloadBytes<terrain::HeightBlock> {
  static size_t of(const terrain::HeightBlock& block) {
    return (block.heights.size() + block.apron.size()) * sizeof(int16_t) +
           (block.exactSurfaceMeters.size() + block.exactApronSurfaceMeters.size()) *
               sizeof(double);
  }
};

using BlockCache = TileCache<terrain::HeightBlock>;
using BlockCacheCounters = TileCacheCounters;

extern template class TileCache<terrain::HeightBlock>;

}  // namespace globe::streaming
