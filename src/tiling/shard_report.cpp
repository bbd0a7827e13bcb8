#include "tiling/shard_report.hpp"

#include <algorithm>

#include "tiling/shard_plan.hpp"
#include "tiling/source_set.hpp"
#include "tiling/tiling_plan.hpp"

namespace globe::tiling {

Result<ShardPlanReport> planShards(const TilerOptions& options) {
  if (options.shardCount == 0) return makeError("--shards must be at least 1");
  auto opened = openSources(options.inputs, {options.verticesPerSide, options.maxLevel,
                                             options.vertical, options.noDataIsSea,
                                             options.allowImages});
  if (!opened) return Error{opened.error()};
  const std::vector<TilerSource>& sources = *opened;
  const TilingPlan plan = planOfSources(sources, options.packTilesPerSide);
  auto shardLevel = chooseShardLevel(options.shardLevel, plan.maxLevel());
  if (!shardLevel) return Error{shardLevel.error()};
  ShardPlanReport report;
  report.maxLevel = plan.maxLevel();
  report.shardLevel = *shardLevel;
  const ShardPartition partition = partitionShards(plan, report.shardLevel, options.shardCount,
                                                   sources, options.packTilesPerSide);
  auto bytesOf = [&](const std::vector<size_t>& used) {
    uint64_t bytes = 0;
    for (size_t i : used)
      bytes += static_cast<uint64_t>(sources[i].grid.cols * sources[i].grid.rows * 2);
    return bytes;
  };
  report.shards.resize(options.shardCount);
  for (uint32_t k = 0; k < options.shardCount; ++k) {
    ShardPlanRow& row = report.shards[k];
    row.units = partition.units[k].size();
    const auto used = sourcesMeeting(
        sources,
        shardRegion(partition.units[k], options.packTilesPerSide, options.verticesPerSide));
    row.sources = used.size();
    row.sourceBytes = bytesOf(used);
  }
  for (uint32_t level = 0; level <= plan.maxLevel(); ++level) {
    for (const formats::PackId& pack : plan.packs(level)) {
      const uint64_t tiles = plan.tilesInPack(pack).size();
      report.wholeTiles += tiles;
      if (level < report.shardLevel) {
        report.merge.tiles += tiles;
        continue;
      }
      const formats::PackId unit = packAncestor(pack, report.shardLevel);
      for (uint32_t k = 0; k < options.shardCount; ++k) {
        if (std::binary_search(partition.units[k].begin(), partition.units[k].end(), unit)) {
          report.shards[k].tiles += tiles;
          break;
        }
      }
    }
  }
  const auto mergeSources =
      sourcesBeyondUnits(sources, plan, report.shardLevel, options.packTilesPerSide);
  report.merge.sources = mergeSources.size();
  report.merge.sourceBytes = bytesOf(mergeSources);
  return report;
}

}  // namespace globe::tiling
