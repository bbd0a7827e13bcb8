// Tiling on many machines: the quadtree cut into shards. A shard's units are the packs of one
// level (the shard level) the plan holds, in Morton order, cut into contiguous runs of about equal
// source samples; a shard builds every pack at and below its units, and reads for the merge the
// heights of the coarser tiles that lie inside them. The merge builds the levels above.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "tiling/source_set.hpp"
#include "tiling/tiling_plan.hpp"

namespace globe::tiling {

// Three levels above the deepest: the merge then builds about 1/192 of the tiles of a pyramid of
// one resolution (and reads the shard level's packs, 1/64), and each unit is 8^2 packs of the
// deepest level (for 30 m data over the world's land, about 10,000 units of 64x64-tile packs).
uint32_t defaultShardLevel(uint32_t maxLevel);

// A pack's rectangle, clipped to the globe.
formats::BoundsDegrees packBoundsDegrees(const formats::PackId& pack, uint32_t packTilesPerSide);

// The plan of the sources (their extents and finest levels), as every run and shard makes it.
TilingPlan planOfSources(const std::vector<TilerSource>& sources, uint32_t packTilesPerSide);

// The shard level: the one asked for, or defaultShardLevel; an error past the deepest level.
Result<uint32_t> chooseShardLevel(std::optional<uint32_t> requested, uint32_t maxLevel);

// The pack of `level` whose tiles hold the point: tiles are closed on their north and west
// edges, the east edge of the last column and the south pole included; longitude wraps.
formats::PackId packHolding(double longitudeDegrees, double latitudeDegrees, uint32_t level,
                            uint32_t packTilesPerSide);

// The ancestor at `level` of a pack at `pack.level` >= level.
formats::PackId packAncestor(const formats::PackId& pack, uint32_t level);

struct ShardPartition {
  uint32_t level = 0;
  std::vector<std::vector<formats::PackId>> units;  // per shard, sorted
  std::vector<double> sourceSamples;  // per shard: the source samples inside its units
  double heaviestUnitSamples = 0;     // no shard exceeds total / N by more than this
};

ShardPartition partitionShards(const TilingPlan& plan, uint32_t shardLevel, uint32_t shardCount,
                               const std::vector<TilerSource>& sources, uint32_t packTilesPerSide);

// Where a shard reads heights: its units, widened by the apron of the shard level, and the polar
// caps of the opposite meridians (the apron beyond a pole) where a unit reaches a pole.
std::vector<formats::BoundsDegrees> shardRegion(const std::vector<formats::PackId>& units,
                                                uint32_t packTilesPerSide,
                                                uint32_t verticesPerSide);

// The sources a height inside the regions may read: those whose extent, widened by its bend
// margin, meets one, with every coarser source their conditioning reads. Ascending indices.
std::vector<size_t> sourcesMeeting(const std::vector<TilerSource>& sources,
                                   const std::vector<formats::BoundsDegrees>& regions);

// The sources the merge reads itself: those whose widened extent meets a pack of the shard level
// the plan lacks (the heights there belong to no shard), with their coarser ones.
std::vector<size_t> sourcesBeyondUnits(const std::vector<TilerSource>& sources,
                                       const TilingPlan& plan, uint32_t shardLevel,
                                       uint32_t packTilesPerSide);

}  // namespace globe::tiling
