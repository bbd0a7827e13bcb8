#include "tiling/shard_samples.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/height_block.hpp"
#include "tiling/sample_positions.hpp"
#include "tiling/shard_files.hpp"
#include "tiling/shard_plan.hpp"

namespace globe::tiling {
namespace {

// Tiles of `level` whose positions may fall inside the units: those touching a unit widened by
// the apron, and where a unit lies within the apron's reach of a pole the whole polar row (its
// apron crosses the pole onto the opposite meridians).
std::set<geo::TileId> candidateTiles(const TilingPlan& plan,
                                     const std::vector<formats::PackId>& units, uint32_t level,
                                     uint32_t n, uint32_t packTiles) {
  std::set<geo::TileId> tiles;
  const double reach = terrain::kApronWidth * terrain::vertexSpacingDegrees(level, n);
  const uint32_t nx = geo::GeographicTilingScheme::tilesX(level);
  const uint32_t ny = geo::GeographicTilingScheme::tilesY(level);
  auto add = [&](uint32_t x, uint32_t y) {
    const geo::TileId tile{level, x, y};
    if (plan.exists(tile)) tiles.insert(tile);
  };
  for (const formats::PackId& unit : units) {
    const formats::BoundsDegrees b = packBoundsDegrees(unit, packTiles);
    const TileRange r =
        tilesTouching({b.west - reach, b.south - reach, b.east + reach, b.north + reach}, level);
    for (uint32_t y = r.y0; y <= r.y1; ++y) {
      for (uint32_t x = r.x0; x <= r.x1; ++x) add(x, y);
    }
    // Beyond ±180° the apron wraps to the other end of the row.
    if (b.west - reach <= -180.0) {
      for (uint32_t y = r.y0; y <= r.y1; ++y) add(nx - 1, y);
    }
    if (b.east + reach >= 180.0) {
      for (uint32_t y = r.y0; y <= r.y1; ++y) add(0, y);
    }
    // The apron beyond a pole lands on the opposite meridians, up to the apron's reach from the
    // pole: a coarse tile's reach spans many units, not only those at the pole.
    for (uint32_t x = 0; x < nx && b.north + reach + 1e-9 >= 90.0; ++x) add(x, 0);
    for (uint32_t x = 0; x < nx && b.south - reach - 1e-9 <= -90.0; ++x) add(x, ny - 1);
  }
  return tiles;
}

}  // namespace

Result<ShardSampleStats> writeShardSamples(const std::filesystem::path& outputDir,
                                           const TilingPlan& plan,
                                           const std::vector<formats::PackId>& units,
                                           uint32_t shardIndex,
                                           const std::vector<TilerSource>& sources,
                                           uint32_t verticesPerSide, uint32_t packTilesPerSide) {
  ShardSampleStats stats;
  if (units.empty()) return stats;
  const uint32_t shardLevel = units.front().level;
  const uint32_t n = verticesPerSide;
  auto mine = [&](const SamplePosition& p) {
    return std::binary_search(
        units.begin(), units.end(),
        packHolding(p.longitudeDegrees, p.latitudeDegrees, shardLevel, packTilesPerSide));
  };
  for (uint32_t level = 0; level < shardLevel; ++level) {
    std::map<formats::PackId, std::set<geo::TileId>> byPack;
    for (const geo::TileId& tile : candidateTiles(plan, units, level, n, packTilesPerSide)) {
      byPack[formats::packOf(tile, packTilesPerSide)].insert(tile);
    }
    for (const auto& [pack, candidates] : byPack) {
      std::vector<SampleRecord> records;
      const std::vector<geo::TileId> tiles = plan.tilesInPack(pack);
      // The same strips as the pack builder's, so every height is read as it would be there.
      for (size_t begin = 0; begin < tiles.size();) {
        size_t end = begin;
        while (end < tiles.size() && tiles[end].y == tiles[begin].y) ++end;
        std::optional<StripSamplers> samplers;
        for (size_t t = begin; t < end; ++t) {
          if (candidates.count(tiles[t]) == 0) continue;
          const auto slot = static_cast<uint32_t>(formats::slotOf(tiles[t], packTilesPerSide));
          for (const SamplePosition& position : sourcePositions(plan, tiles[t], n)) {
            if (!mine(position)) continue;
            if (!samplers) samplers.emplace(sources, plan, tiles[begin], tiles[end - 1], n);
            auto height = samplers->sample(position);
            if (!height) return Error{height.error()};
            records.push_back({slot, position.index, *height});
          }
        }
        begin = end;
      }
      if (records.empty()) continue;
      stats.samples += records.size();
      ++stats.fragments;
      if (auto written = writeSampleFragment(outputDir, pack, shardIndex, positionsPerTile(n),
                                             std::move(records));
          !written) {
        return Error{written.error()};
      }
    }
  }
  return stats;
}

}  // namespace globe::tiling
