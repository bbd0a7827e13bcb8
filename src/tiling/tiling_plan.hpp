// Which tiles the pyramid holds at each level: every tile that touches a source fine enough for
// that level, with its three siblings, plus the parents of every such tile, so levels deepen only
// where finer data exists and a tile has either no children or all four.
#pragma once

#include <cstdint>
#include <vector>

#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "geo/tile_id.hpp"

namespace globe::tiling {

// Inclusive tile index rectangle at one level.
struct TileRange {
  uint32_t x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  bool contains(uint32_t x, uint32_t y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
  bool intersects(const TileRange& o) const {
    return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1;
  }
};

// Tiles whose closed rectangle may touch the closed extent; errs on the side of one more tile,
// never one fewer, so a vertex a source covers always lies in an existing tile.
TileRange tilesTouching(const formats::BoundsDegrees& extent, uint32_t level);

class TilingPlan {
 public:
  // extents[i] with finestLevels[i]: each source's extent and deepest level.
  TilingPlan(const std::vector<formats::BoundsDegrees>& extents,
             const std::vector<uint32_t>& finestLevels, uint32_t packTilesPerSide);

  uint32_t maxLevel() const { return static_cast<uint32_t>(levels_.size()) - 1; }
  bool exists(const geo::TileId& tile) const;
  const std::vector<formats::PackId>& packs(uint32_t level) const { return levels_[level].packs; }
  // Tiles of the pack that the plan holds, in slot order.
  std::vector<geo::TileId> tilesInPack(const formats::PackId& pack) const;
  uint64_t tileCount(uint32_t level) const;

 private:
  struct Level {
    std::vector<TileRange> ranges;
    std::vector<formats::PackId> packs;  // sorted
  };
  std::vector<Level> levels_;
  uint32_t packTilesPerSide_;
};

}  // namespace globe::tiling
