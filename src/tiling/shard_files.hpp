// What the shards leave for the merge in OUT/shards/: a summary per finished shard (the packs it
// built, the sources it conditioned) and, per pack of a level above the shard level, the heights
// its units hold (fragments). The merge removes the folder once the manifest is written.
#pragma once

#include <cstdint>
#include <filesystem>
#include <utility>
#include <vector>

#include "core/result.hpp"
#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "tiling/pack_summary.hpp"
#include "tiling/sample_table.hpp"

namespace globe::tiling {

std::filesystem::path shardFolder(const std::filesystem::path& outputDir);

struct SampleRecord {
  uint32_t slot = 0;
  uint32_t index = 0;  // tiling/sample_positions.hpp
  int16_t heightCode = 0;
};

// Written atomically; records sorted by slot and index.
Result<void> writeSampleFragment(const std::filesystem::path& outputDir,
                                 const formats::PackId& pack, uint32_t shardIndex,
                                 uint32_t positionsPerTile, std::vector<SampleRecord> records);

// Every shard's fragment of the pack into the table (none: nothing added).
Result<void> readSampleFragments(const std::filesystem::path& outputDir,
                                 const formats::PackId& pack, uint32_t positionsPerTile,
                                 SampleTable& table);

struct ShardSummary {
  uint32_t index = 0, count = 1, level = 0;
  std::string planFingerprint;  // the run's tiling-plan.json, so stale shards are caught
  std::vector<std::pair<formats::PackId, PackSummary>> packs;
  std::vector<std::pair<size_t, formats::SourceConditioning>> conditioning;  // by source index
};

Result<void> writeShardSummary(const std::filesystem::path& outputDir, const ShardSummary& summary);

// Every shard's summary; an error naming the first shard missing (not finished) or disagreeing
// with the others or with the plan.
Result<std::vector<ShardSummary>> readShardSummaries(const std::filesystem::path& outputDir,
                                                     const std::string& planFingerprint);

}  // namespace globe::tiling
