// A shard's part of the levels above the shard level: the heights from the sources of every
// tile there (vertices no child fills, the apron) that lie inside the shard's units, written as
// one fragment per pack for the merge (tiling/shard_files.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/result.hpp"
#include "formats/pack_format.hpp"
#include "tiling/source_set.hpp"
#include "tiling/tiling_plan.hpp"

namespace globe::tiling {

struct ShardSampleStats {
  uint64_t fragments = 0;
  uint64_t samples = 0;
};

// units: the shard's packs of the shard level (sorted); sources: the ones its region needs.
Result<ShardSampleStats> writeShardSamples(const std::filesystem::path& outputDir,
                                           const TilingPlan& plan,
                                           const std::vector<formats::PackId>& units,
                                           uint32_t shardIndex,
                                           const std::vector<TilerSource>& sources,
                                           uint32_t verticesPerSide, uint32_t packTilesPerSide);

}  // namespace globe::tiling
