#include "tiling/shard_plan.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/height_block.hpp"
#include "tiling/source_conditioning.hpp"

namespace globe::tiling {
namespace {

constexpr double kSlackDegrees = 1e-9;

double tileDegrees(uint32_t level) { return std::ldexp(180.0, -static_cast<int>(level)); }

uint64_t mortonKey(uint32_t x, uint32_t y) {
  uint64_t key = 0;
  for (int bit = 0; bit < 32; ++bit) {
    key |= (uint64_t{(x >> bit) & 1U} << (2 * bit)) | (uint64_t{(y >> bit) & 1U} << (2 * bit + 1));
  }
  return key;
}

bool rectsMeet(const formats::BoundsDegrees& a, const formats::BoundsDegrees& b) {
  return a.west <= b.east + kSlackDegrees && b.west <= a.east + kSlackDegrees &&
         a.south <= b.north + kSlackDegrees && b.south <= a.north + kSlackDegrees;
}

// A rectangle whose longitudes may run past ±180°, as the pieces inside [-180, 180].
void addWrapped(std::vector<formats::BoundsDegrees>& out, formats::BoundsDegrees r) {
  r.south = std::max(r.south, -90.0);
  r.north = std::min(r.north, 90.0);
  if (r.east - r.west >= 360.0) {
    out.push_back({-180.0, r.south, 180.0, r.north});
    return;
  }
  if (r.west < -180.0) out.push_back({r.west + 360.0, r.south, 180.0, r.north});
  if (r.east > 180.0) out.push_back({-180.0, r.south, r.east - 360.0, r.north});
  out.push_back({std::max(r.west, -180.0), r.south, std::min(r.east, 180.0), r.north});
}

// Where a source's samples or its bend reach.
std::vector<std::vector<formats::BoundsDegrees>> influence(
    const std::vector<TilerSource>& sources) {
  const auto coarser = coarserSourcesReaching(sources);
  std::vector<std::vector<formats::BoundsDegrees>> pieces(sources.size());
  for (size_t i = 0; i < sources.size(); ++i) {
    const TilerSource& s = sources[i];
    const double margin = bendMarginDegrees(sources, coarser[i]);
    formats::BoundsDegrees r{s.extent.west - margin, s.extent.south - margin,
                             s.extent.east + margin, s.extent.north + margin};
    if (s.grid.wrapsLongitude) r.west = -180.0, r.east = 180.0;
    addWrapped(pieces[i], r);
  }
  return pieces;
}

std::vector<size_t> withCoarser(const std::vector<TilerSource>& sources,
                                std::vector<uint8_t> needed) {
  const auto coarser = coarserSourcesReaching(sources);
  // Coarser sources come later (finest first), so one pass in order closes the set.
  for (size_t i = 0; i < sources.size(); ++i) {
    if (needed[i] == 0) continue;
    for (size_t j : coarser[i]) needed[j] = 1;
  }
  std::vector<size_t> indices;
  for (size_t i = 0; i < sources.size(); ++i) {
    if (needed[i] != 0) indices.push_back(i);
  }
  return indices;
}

// Packs of `level` a closed rectangle touches.
template <typename F>
void forEachPackTouching(const formats::BoundsDegrees& r, uint32_t level, uint32_t packTiles,
                         F&& visit) {
  const TileRange tiles = tilesTouching(r, level);
  for (uint32_t py = tiles.y0 / packTiles; py <= tiles.y1 / packTiles; ++py) {
    for (uint32_t px = tiles.x0 / packTiles; px <= tiles.x1 / packTiles; ++px) {
      visit(formats::PackId{level, px, py});
    }
  }
}

}  // namespace

TilingPlan planOfSources(const std::vector<TilerSource>& sources, uint32_t packTilesPerSide) {
  std::vector<formats::BoundsDegrees> extents;
  std::vector<uint32_t> finestLevels;
  for (const TilerSource& s : sources) {
    extents.push_back(s.extent);
    finestLevels.push_back(s.finestLevel);
  }
  return TilingPlan(extents, finestLevels, packTilesPerSide);
}

Result<uint32_t> chooseShardLevel(std::optional<uint32_t> requested, uint32_t maxLevel) {
  const uint32_t level = requested.value_or(defaultShardLevel(maxLevel));
  if (level > maxLevel) {
    return makeError("--shard-level " + std::to_string(level) + " is below the deepest level (" +
                     std::to_string(maxLevel) + ")");
  }
  return level;
}

uint32_t defaultShardLevel(uint32_t maxLevel) { return maxLevel >= 3 ? maxLevel - 3 : 0; }

formats::BoundsDegrees packBoundsDegrees(const formats::PackId& pack, uint32_t packTilesPerSide) {
  const double degrees = tileDegrees(pack.level) * packTilesPerSide;
  return {-180.0 + pack.x * degrees, std::max(-90.0, 90.0 - (pack.y + 1) * degrees),
          std::min(180.0, -180.0 + (pack.x + 1) * degrees), 90.0 - pack.y * degrees};
}

formats::PackId packHolding(double longitudeDegrees, double latitudeDegrees, uint32_t level,
                            uint32_t packTilesPerSide) {
  const double degrees = tileDegrees(level);
  const uint32_t nx = geo::GeographicTilingScheme::tilesX(level);
  const uint32_t ny = geo::GeographicTilingScheme::tilesY(level);
  double lon = longitudeDegrees;
  if (lon < -180.0 || lon > 180.0)
    lon = std::fmod(std::fmod(lon + 180.0, 360.0) + 360.0, 360.0) - 180.0;
  const auto clampIndex = [](double v, uint32_t count) {
    return static_cast<uint32_t>(std::clamp(std::floor(v), 0.0, static_cast<double>(count - 1)));
  };
  const uint32_t x = clampIndex((lon + 180.0) / degrees, nx);
  const uint32_t y = clampIndex((90.0 - latitudeDegrees) / degrees, ny);
  return {level, x / packTilesPerSide, y / packTilesPerSide};
}

formats::PackId packAncestor(const formats::PackId& pack, uint32_t level) {
  const uint32_t up = pack.level - level;
  return {level, pack.x >> up, pack.y >> up};
}

ShardPartition partitionShards(const TilingPlan& plan, uint32_t shardLevel, uint32_t shardCount,
                               const std::vector<TilerSource>& sources, uint32_t packTilesPerSide) {
  const std::vector<formats::PackId>& packs = plan.packs(shardLevel);
  std::map<formats::PackId, size_t> unitIndex;
  for (size_t i = 0; i < packs.size(); ++i) unitIndex.emplace(packs[i], i);
  // Weight: the source samples inside each unit, plus one so that empty units still spread.
  std::vector<double> weight(packs.size(), 1.0);
  for (const TilerSource& s : sources) {
    const double cellArea = s.grid.columnStepDegrees * s.grid.rowStepDegrees;
    if (!(cellArea > 0)) continue;
    formats::BoundsDegrees extent = s.extent;
    if (s.grid.wrapsLongitude) extent.west = -180.0, extent.east = 180.0;
    forEachPackTouching(extent, shardLevel, packTilesPerSide, [&](const formats::PackId& pack) {
      const auto found = unitIndex.find(pack);
      if (found == unitIndex.end()) return;
      const formats::BoundsDegrees b = packBoundsDegrees(pack, packTilesPerSide);
      const double w = std::min(b.east, extent.east) - std::max(b.west, extent.west);
      const double h = std::min(b.north, extent.north) - std::max(b.south, extent.south);
      if (w > 0 && h > 0) weight[found->second] += w * h / cellArea;
    });
  }
  std::vector<size_t> order(packs.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return mortonKey(packs[a].x, packs[a].y) < mortonKey(packs[b].x, packs[b].y);
  });
  double total = 0;
  for (double w : weight) total += w;
  ShardPartition partition;
  partition.level = shardLevel;
  partition.units.resize(shardCount);
  partition.sourceSamples.assign(shardCount, 0.0);
  double before = 0;
  for (size_t i : order) {
    // A unit goes to the shard its middle falls in: contiguous runs of about total/N each.
    const double middle = (before + weight[i] / 2) / total;
    const auto shard =
        std::min<uint32_t>(shardCount - 1, static_cast<uint32_t>(std::floor(middle * shardCount)));
    partition.units[shard].push_back(packs[i]);
    partition.sourceSamples[shard] += weight[i] - 1.0;
    partition.heaviestUnitSamples = std::max(partition.heaviestUnitSamples, weight[i] - 1.0);
    before += weight[i];
  }
  for (auto& units : partition.units) std::sort(units.begin(), units.end());
  return partition;
}

std::vector<formats::BoundsDegrees> shardRegion(const std::vector<formats::PackId>& units,
                                                uint32_t packTilesPerSide,
                                                uint32_t verticesPerSide) {
  std::vector<formats::BoundsDegrees> region;
  for (const formats::PackId& unit : units) {
    const double reach =
        terrain::kApronWidth * terrain::vertexSpacingDegrees(unit.level, verticesPerSide) +
        kSlackDegrees;
    const formats::BoundsDegrees b = packBoundsDegrees(unit, packTilesPerSide);
    addWrapped(region, {b.west - reach, b.south - reach, b.east + reach, b.north + reach});
    if (b.north >= 90.0) region.push_back({-180.0, 90.0 - 2 * reach, 180.0, 90.0});
    if (b.south <= -90.0) region.push_back({-180.0, -90.0, 180.0, -90.0 + 2 * reach});
  }
  return region;
}

std::vector<size_t> sourcesMeeting(const std::vector<TilerSource>& sources,
                                   const std::vector<formats::BoundsDegrees>& regions) {
  const auto pieces = influence(sources);
  std::vector<uint8_t> needed(sources.size(), 0);
  for (size_t i = 0; i < sources.size(); ++i) {
    for (const formats::BoundsDegrees& piece : pieces[i]) {
      if (std::any_of(regions.begin(), regions.end(),
                      [&](const formats::BoundsDegrees& r) { return rectsMeet(piece, r); })) {
        needed[i] = 1;
        break;
      }
    }
  }
  return withCoarser(sources, std::move(needed));
}

std::vector<size_t> sourcesBeyondUnits(const std::vector<TilerSource>& sources,
                                       const TilingPlan& plan, uint32_t shardLevel,
                                       uint32_t packTilesPerSide) {
  const std::vector<formats::PackId>& units = plan.packs(shardLevel);
  const auto pieces = influence(sources);
  std::vector<uint8_t> needed(sources.size(), 0);
  for (size_t i = 0; i < sources.size(); ++i) {
    for (const formats::BoundsDegrees& piece : pieces[i]) {
      const formats::BoundsDegrees widened{piece.west - kSlackDegrees, piece.south - kSlackDegrees,
                                           piece.east + kSlackDegrees, piece.north + kSlackDegrees};
      forEachPackTouching(widened, shardLevel, packTilesPerSide, [&](const formats::PackId& p) {
        if (!std::binary_search(units.begin(), units.end(), p)) needed[i] = 1;
      });
    }
  }
  return withCoarser(sources, std::move(needed));
}

}  // namespace globe::tiling
