// Which imagery tiles and packs a layer will have: at each level, the tiles over the footprint of
// every input whose finest level is that deep or deeper (coarser inputs only paint under them).
#pragma once

#include <cstdint>
#include <vector>

#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "geo/tile_id.hpp"

namespace globe::imagery_tiling {

struct ImageryTileRange {
  uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // inclusive
  bool contains(uint32_t x, uint32_t y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

// The tiles of `level` that overlap the extent (a tile merely touching it is left out).
ImageryTileRange tileRangeOf(const formats::BoundsDegrees& extent, uint32_t level);

class ImageryPlan {
 public:
  // extents[i] is tiled from level 0 down to finestLevels[i].
  ImageryPlan(const std::vector<formats::BoundsDegrees>& extents,
              const std::vector<uint32_t>& finestLevels, uint32_t packTilesPerSide);

  uint32_t maxLevel() const { return static_cast<uint32_t>(ranges_.size()) - 1; }
  const std::vector<formats::PackId>& packs(uint32_t level) const { return packs_[level]; }
  bool planned(const geo::TileId& tile) const;
  // The planned tiles of a pack, in slot order.
  std::vector<geo::TileId> tilesInPack(const formats::PackId& pack) const;
  uint64_t tileCount() const { return tileCount_; }

 private:
  uint32_t packTilesPerSide_;
  std::vector<std::vector<ImageryTileRange>> ranges_;  // per level
  std::vector<std::vector<formats::PackId>> packs_;    // per level, sorted
  uint64_t tileCount_ = 0;
};

}  // namespace globe::imagery_tiling
