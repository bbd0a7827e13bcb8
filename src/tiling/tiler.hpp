// globe-tiler's job: builds a tile pyramid from rasters, level by level from the finest, packs
// in parallel, every file written atomically, resumable after a kill.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "formats/vertical_units.hpp"
#include "geo/ellipsoid.hpp"
#include "tiling/progress.hpp"

namespace globe::tiling {

// The whole pyramid on one machine; one shard of it (tiling/shard_plan.hpp: the packs at and
// below the shard's units, and the heights inside them the merge needs); or the merge after every
// shard (the levels above the shard level and the manifest): byte-identical to the whole run.
enum class TilerRole { Whole, Shard, Merge };

struct TilerOptions {
  std::vector<std::string> inputs;
  std::filesystem::path outputDir;
  uint32_t verticesPerSide = 17;
  uint32_t packTilesPerSide = 64;
  std::optional<uint32_t> maxLevel;
  geo::GlobeModel globeModel = geo::GlobeModel::Wgs84;
  unsigned threads = 0;                  // 0 = every core
  ProgressSink progress;                 // how far the run is; empty: not reported
  formats::VerticalOverride vertical{};  // --z-units / --z-scale: replace every input's own unit
  bool noDataIsSea = false;              // --no-data-is-sea: every input's no data is water
  bool allowImages = false;              // --force: tile a colour image's band 1 as heights
  TilerRole role = TilerRole::Whole;
  uint32_t shardIndex = 0, shardCount = 1;  // TilerRole::Shard
  std::optional<uint32_t> shardLevel;       // TilerRole::Shard (default: defaultShardLevel)
};

struct TilerReport {
  uint64_t tiles = 0;
  uint64_t packsBuilt = 0;
  uint64_t packsReused = 0;  // complete packs found from an earlier, interrupted run
  uint64_t sourceBytes = 0;
  uint64_t sampledVertices = 0;
  uint64_t sourcesConditioned = 0;  // a shard or the merge conditions only the sources it reads
  uint64_t fragments = 0;           // a shard's height fragments for the merge
  bool alreadyMerged = false;       // a merge found its work done (manifest, no shards left)
  double seconds = 0;
  std::vector<std::string> warnings;  // one line each, naming the input
};

Result<TilerReport> runTiler(const TilerOptions& options);

}  // namespace globe::tiling
