#include "tiling/tiling_plan.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include "geo/tiling_scheme.hpp"

namespace globe::tiling {
namespace {

uint32_t clampIndex(double value, uint32_t count) {
  return static_cast<uint32_t>(std::clamp(value, 0.0, static_cast<double>(count - 1)));
}

}  // namespace

TileRange tilesTouching(const formats::BoundsDegrees& extent, uint32_t level) {
  const double tileDegrees = std::ldexp(180.0, -static_cast<int>(level));
  const uint32_t nx = geo::GeographicTilingScheme::tilesX(level);
  const uint32_t ny = geo::GeographicTilingScheme::tilesY(level);
  constexpr double kSlack = 1e-9;  // in tiles
  // Tile x spans [x·w, (x+1)·w] from −180°: it touches [west, east] when x ≥ ⌈a⌉−1 and x ≤ ⌊b⌋.
  const double a = (extent.west + 180.0) / tileDegrees;
  const double b = (extent.east + 180.0) / tileDegrees;
  const double c = (90.0 - extent.north) / tileDegrees;
  const double d = (90.0 - extent.south) / tileDegrees;
  return {clampIndex(std::ceil(a - kSlack) - 1, nx), clampIndex(std::floor(b + kSlack), nx),
          clampIndex(std::ceil(c - kSlack) - 1, ny), clampIndex(std::floor(d + kSlack), ny)};
}

TilingPlan::TilingPlan(const std::vector<formats::BoundsDegrees>& extents,
                       const std::vector<uint32_t>& finestLevels, uint32_t packTilesPerSide)
    : packTilesPerSide_(packTilesPerSide) {
  const uint32_t maxLevel = *std::max_element(finestLevels.begin(), finestLevels.end());
  levels_.resize(maxLevel + 1);
  for (uint32_t level = maxLevel + 1; level-- > 0;) {
    Level& current = levels_[level];
    for (size_t i = 0; i < extents.size(); ++i) {
      if (finestLevels[i] < level) continue;
      TileRange r = tilesTouching(extents[i], level);
      if (level > 0) {
        // Whole families of four: a viewer refines a tile only when all its children exist.
        r = {r.x0 & ~1U, r.x1 | 1U, r.y0 & ~1U, r.y1 | 1U};
      }
      current.ranges.push_back(r);
    }
    if (level < maxLevel) {  // parents of every finer tile
      for (const TileRange& r : levels_[level + 1].ranges) {
        current.ranges.push_back({r.x0 / 2, r.x1 / 2, r.y0 / 2, r.y1 / 2});
      }
    }
    // Parent ranges mostly repeat the sources' own ranges at this level: keep each once.
    auto key = [](const TileRange& r) { return std::tuple(r.x0, r.x1, r.y0, r.y1); };
    std::sort(current.ranges.begin(), current.ranges.end(),
              [&](const TileRange& l, const TileRange& r) { return key(l) < key(r); });
    current.ranges.erase(
        std::unique(current.ranges.begin(), current.ranges.end(),
                    [&](const TileRange& l, const TileRange& r) { return key(l) == key(r); }),
        current.ranges.end());
    std::set<formats::PackId> packs;
    for (const TileRange& r : current.ranges) {
      for (uint32_t py = r.y0 / packTilesPerSide; py <= r.y1 / packTilesPerSide; ++py) {
        for (uint32_t px = r.x0 / packTilesPerSide; px <= r.x1 / packTilesPerSide; ++px) {
          packs.insert({level, px, py});
        }
      }
    }
    current.packs.assign(packs.begin(), packs.end());
  }
}

bool TilingPlan::exists(const geo::TileId& tile) const {
  if (tile.level >= levels_.size()) return false;
  for (const TileRange& r : levels_[tile.level].ranges) {
    if (r.contains(tile.x, tile.y)) return true;
  }
  return false;
}

std::vector<geo::TileId> TilingPlan::tilesInPack(const formats::PackId& pack) const {
  const uint32_t p = packTilesPerSide_;
  const TileRange packRange{pack.x * p, pack.x * p + p - 1, pack.y * p, pack.y * p + p - 1};
  std::vector<TileRange> ranges;
  for (const TileRange& r : levels_[pack.level].ranges) {
    if (r.intersects(packRange)) ranges.push_back(r);
  }
  std::vector<geo::TileId> tiles;
  for (uint32_t y = packRange.y0; y <= packRange.y1; ++y) {
    for (uint32_t x = packRange.x0; x <= packRange.x1; ++x) {
      if (std::any_of(ranges.begin(), ranges.end(),
                      [&](const TileRange& r) { return r.contains(x, y); })) {
        tiles.push_back({pack.level, x, y});
      }
    }
  }
  return tiles;
}

uint64_t TilingPlan::tileCount(uint32_t level) const {
  uint64_t count = 0;
  for (const formats::PackId& pack : levels_[level].packs) count += tilesInPack(pack).size();
  return count;
}

}  // namespace globe::tiling
