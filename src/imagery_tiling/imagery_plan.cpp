#include "imagery_tiling/imagery_plan.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "geo/tiling_scheme.hpp"

namespace globe::imagery_tiling {

ImageryTileRange tileRangeOf(const formats::BoundsDegrees& extent, uint32_t level) {
  const double size = std::ldexp(180.0, -static_cast<int>(level));
  const auto columns = static_cast<int64_t>(geo::GeographicTilingScheme::tilesX(level));
  const auto rows = static_cast<int64_t>(geo::GeographicTilingScheme::tilesY(level));
  auto clampTo = [](double value, int64_t count) {
    return static_cast<uint32_t>(std::clamp<int64_t>(static_cast<int64_t>(value), 0, count - 1));
  };
  return {clampTo(std::floor((extent.west + 180) / size), columns),
          clampTo(std::floor((90 - extent.north) / size), rows),
          clampTo(std::ceil((extent.east + 180) / size) - 1, columns),
          clampTo(std::ceil((90 - extent.south) / size) - 1, rows)};
}

ImageryPlan::ImageryPlan(const std::vector<formats::BoundsDegrees>& extents,
                         const std::vector<uint32_t>& finestLevels, uint32_t packTilesPerSide)
    : packTilesPerSide_(packTilesPerSide) {
  const uint32_t deepest = *std::max_element(finestLevels.begin(), finestLevels.end());
  ranges_.resize(deepest + 1);
  packs_.resize(deepest + 1);
  for (uint32_t level = 0; level <= deepest; ++level) {
    std::set<formats::PackId> packs;
    for (size_t i = 0; i < extents.size(); ++i) {
      if (finestLevels[i] < level) continue;
      const ImageryTileRange range = tileRangeOf(extents[i], level);
      ranges_[level].push_back(range);
      for (uint32_t py = range.y0 / packTilesPerSide; py <= range.y1 / packTilesPerSide; ++py) {
        for (uint32_t px = range.x0 / packTilesPerSide; px <= range.x1 / packTilesPerSide; ++px) {
          packs.insert({level, px, py});
        }
      }
    }
    packs_[level].assign(packs.begin(), packs.end());
    for (const formats::PackId& pack : packs_[level]) tileCount_ += tilesInPack(pack).size();
  }
}

bool ImageryPlan::planned(const geo::TileId& tile) const {
  if (tile.level >= ranges_.size()) return false;
  return std::any_of(ranges_[tile.level].begin(), ranges_[tile.level].end(),
                     [&](const ImageryTileRange& r) { return r.contains(tile.x, tile.y); });
}

std::vector<geo::TileId> ImageryPlan::tilesInPack(const formats::PackId& pack) const {
  std::vector<geo::TileId> tiles;
  const uint32_t p = packTilesPerSide_;
  for (uint32_t y = pack.y * p; y < (pack.y + 1) * p; ++y) {
    for (uint32_t x = pack.x * p; x < (pack.x + 1) * p; ++x) {
      if (planned({pack.level, x, y})) tiles.push_back({pack.level, x, y});
    }
  }
  return tiles;
}

}  // namespace globe::imagery_tiling
