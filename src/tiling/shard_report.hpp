// The planning step before a sharded run: what each shard will build and read, from the inputs'
// headers alone (nothing is conditioned or written).
#pragma once

#include <cstdint>
#include <vector>

#include "core/result.hpp"
#include "tiling/tiler.hpp"

namespace globe::tiling {

struct ShardPlanRow {
  uint64_t units = 0;        // packs of the shard level
  uint64_t tiles = 0;        // tiles it builds
  uint64_t sources = 0;      // sources it reads (its units' and their halo's, coarser ones)
  uint64_t sourceBytes = 0;  // their samples, 2 bytes each
};

struct ShardPlanReport {
  uint32_t shardLevel = 0;
  uint32_t maxLevel = 0;
  std::vector<ShardPlanRow> shards;
  ShardPlanRow merge;  // units: 0
  uint64_t wholeTiles = 0;
};

// options.shardCount shards (options.shardLevel or the default level).
Result<ShardPlanReport> planShards(const TilerOptions& options);

}  // namespace globe::tiling
