#include "tiling/tiler.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "formats/vertical_units.hpp"
#include "geo/tiling_scheme.hpp"
#include "tiling/pack_builder.hpp"
#include "tiling/pack_summary.hpp"
#include "tiling/progress.hpp"
#include "tiling/shard_files.hpp"
#include "tiling/shard_plan.hpp"
#include "tiling/shard_samples.hpp"
#include "tiling/source_conditioning.hpp"
#include "tiling/source_set.hpp"
#include "tiling/tiling_plan.hpp"
#include "tiling/write_failed.hpp"
#include "transport/atomic_file.hpp"

namespace globe::tiling {
namespace {

namespace fs = std::filesystem;
constexpr const char* kPlanFileName = "tiling-plan.json";
constexpr uint64_t kMaxPackBytes = uint64_t{1} << 33;
// Names the sea/void/fill/footprint rules: a pyramid resumed under other rules would mix them.
constexpr const char* kConditioningVersion = "sea-void-fill-footprint 2";

// Everything that decides the pyramid's content: a resumed run must match it exactly.
std::string planFingerprint(const TilerOptions& options, const std::vector<TilerSource>& sources) {
  nlohmann::json inputs = nlohmann::json::array();
  for (const TilerSource& s : sources) {
    std::error_code error;
    const auto bytes = fs::file_size(s.rasterPath, error);
    inputs.push_back({{"path", s.argument},
                      {"bytes", error ? 0 : bytes},
                      {"columns", s.grid.cols},
                      {"rows", s.grid.rows},
                      {"stepDegrees", s.stepDegrees},
                      {"finestLevel", s.finestLevel},
                      {"noDataIsWater", s.noDataIsWater},
                      {"verticalUnits", formats::describe(s.verticalUnits)}});
  }
  const nlohmann::json plan = {
      {"inputs", inputs},
      {"blockSize", options.verticesPerSide},
      {"packTilesPerSide", options.packTilesPerSide},
      {"globeModel", std::string(geo::toString(options.globeModel))},
      {"conditioning", kConditioningVersion},
      {"geometricError",
       {{"ignoredFraction", kDeviationIgnoredFraction}, {"maxFraction", kDeviationMaxFraction}}}};
  return plan.dump(1) + "\n";
}

// A failed write leaves no half-written file (io::writeFileAtomically), so the run can resume.

Result<void> prepareOutput(const TilerOptions& options, const std::string& fingerprint) {
  std::error_code error;
  fs::create_directories(options.outputDir, error);
  if (error) return makeError(options.outputDir.string() + ": cannot create: " + error.message());
  // A killed run's half-written files; not while other shards may be writing theirs (the merge
  // removes what killed shards left).
  if (options.role != TilerRole::Shard) transport::removeAtomicTemporaries(options.outputDir);
  const fs::path planPath = options.outputDir / kPlanFileName;
  if (fs::exists(planPath, error)) {
    auto existing = transport::readWholeFile(planPath, 1 << 24);
    if (!existing) return Error{existing.error()};
    const std::string text(reinterpret_cast<const char*>(existing->data()), existing->size());
    if (text != fingerprint) {
      return makeError(options.outputDir.string() +
                       ": holds a pyramid made from other inputs or options; remove it or choose "
                       "another output directory");
    }
    return {};
  }
  if (options.role == TilerRole::Merge) {
    return makeError(options.outputDir.string() + ": no " + kPlanFileName +
                     ": run the shards (globe-tiler --shard K/N) into it first");
  }
  if (fs::exists(options.outputDir / formats::kManifestFileName, error)) {
    return makeError(options.outputDir.string() + ": holds a pyramid without " + kPlanFileName +
                     "; remove it or choose another output directory");
  }
  if (auto written = transport::writeFileAtomically(planPath, fingerprint); !written) {
    return writeFailed(written.error());
  }
  return {};
}

Result<formats::Pack> readPack(const fs::path& path) {
  auto bytes = transport::readWholeFile(path, kMaxPackBytes);
  if (!bytes) return Error{bytes.error()};
  return formats::decodePack(*bytes, path);
}

// Builds (or, after an interrupted run, re-validates) one pack.
struct PackJob {
  const TilerOptions& options;
  const formats::PackLayout& layout;
  const TilingPlan& plan;
  const std::vector<TilerSource>& sources;
  std::function<Result<PrecomputedSamples>(const formats::PackId&, SampleTable&)> precomputed;

  Result<PackSummary> run(const formats::PackId& id, bool& reused, PackBuildStats& stats) const {
    const fs::path path = formats::packPath(options.outputDir, id);
    reused = false;
    std::error_code error;
    if (fs::exists(path, error)) {  // an unreadable path (a symlink loop) is rebuilt too
      auto existing = readPack(path);
      if (existing && existing->id == id && existing->layout.tilesPerSide == layout.tilesPerSide &&
          existing->layout.verticesPerSide == layout.verticesPerSide &&
          existing->layout.formatVersion == formats::kPackFormatVersion) {
        reused = true;
        PackSummary summary = summarise(*existing);
        summary.indexBytes = existing->layout.indexBytes;
        return summary;
      }
    }
    std::map<formats::PackId, formats::Pack> children;
    if (id.level < plan.maxLevel()) {
      const auto& finer = plan.packs(id.level + 1);
      for (uint32_t dy = 0; dy < 2; ++dy) {
        for (uint32_t dx = 0; dx < 2; ++dx) {
          const formats::PackId child{id.level + 1, 2 * id.x + dx, 2 * id.y + dy};
          if (!std::binary_search(finer.begin(), finer.end(), child)) continue;
          auto pack = readPack(formats::packPath(options.outputDir, child));
          if (!pack) return Error{pack.error()};
          children.emplace(child, std::move(*pack));
        }
      }
    }
    PrecomputedSamples heights;
    std::optional<SampleTable> table;
    if (precomputed) {
      table.emplace(layout.tilesPerSide * layout.tilesPerSide, layout.verticesPerSide);
      auto found = precomputed(id, *table);
      if (!found) return Error{found.error()};
      heights = *found;
    }
    auto pack = buildPack(id, layout, plan, sources, children,
                          geo::ellipsoidFor(options.globeModel), stats, heights);
    if (!pack) return Error{pack.error()};
    fs::create_directories(path.parent_path(), error);
    if (error)
      return makeError(path.parent_path().string() + ": cannot create: " + error.message());
    const std::vector<std::byte> bytes = formats::encodePack(*pack);
    if (auto written = transport::writeFileAtomically(path, bytes); !written) {
      return writeFailed(written.error());
    }
    PackSummary summary = summarise(*pack);
    const auto indexEnd = formats::packIndexEndOffset(bytes);
    if (pack->layout.hasCompressedIndex() && indexEnd) {
      summary.indexBytes = static_cast<uint32_t>(*indexEnd - formats::kPackHeaderBytes);
    }
    return summary;
  }
};

// The sources this run reads, by index into all of them: every one for the whole run; for a
// shard, those its region needs; for the merge, those the heights of no shard need.
std::vector<size_t> sourcesOfRole(const TilerOptions& options, const TilingPlan& plan,
                                  const std::vector<TilerSource>& sources,
                                  const ShardPartition* partition, uint32_t shardLevel) {
  if (options.role == TilerRole::Shard) {
    return sourcesMeeting(sources, shardRegion(partition->units[options.shardIndex],
                                               options.packTilesPerSide, options.verticesPerSide));
  }
  if (options.role == TilerRole::Merge) {
    return sourcesBeyondUnits(sources, plan, shardLevel, options.packTilesPerSide);
  }
  std::vector<size_t> all(sources.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = i;
  return all;
}

Result<void> checkOptions(const TilerOptions& options) {
  if (!terrain::isValidBlockSize(options.verticesPerSide)) {
    return makeError("block size " + std::to_string(options.verticesPerSide) +
                     " is not 2^k+1 between 3 and 1025");
  }
  if (options.packTilesPerSide == 0 || options.packTilesPerSide > 1024) {
    return makeError("tiles per pack side must be between 1 and 1024");
  }
  if (options.maxLevel && *options.maxLevel > geo::kMaxLevel) {
    return makeError("--max-level must be at most " + std::to_string(geo::kMaxLevel));
  }
  if (options.role == TilerRole::Shard && options.shardIndex >= options.shardCount) {
    return makeError("shard " + std::to_string(options.shardIndex) + " of " +
                     std::to_string(options.shardCount) + ": K must be below N");
  }
  return {};
}

// --z-units / --z-scale given, and an input states its own unit: it keeps it, and says so.
void warnOfKeptUnits(const TilerOptions& options, const std::vector<TilerSource>& sources,
                     std::vector<std::string>& warnings) {
  if (!options.vertical.units && !options.vertical.metersPerUnit) return;
  for (const TilerSource& s : sources) {
    const formats::VerticalUnitOrigin origin = s.verticalUnits.origin;
    if (origin != formats::VerticalUnitOrigin::File &&
        origin != formats::VerticalUnitOrigin::Format) {
      continue;
    }
    warnings.push_back(s.argument + ": keeps its own unit (" + formats::describe(s.verticalUnits) +
                       "): --z-units / --z-scale apply to inputs that state none");
  }
}

// Only a source whose no data is its water code can be all no data (others are refused).
void warnOfAllSea(const std::vector<TilerSource>& sources,
                  const std::vector<formats::SourceConditioning>& conditioning,
                  std::vector<std::string>& warnings) {
  for (size_t i = 0; i < sources.size(); ++i) {
    const auto samples = static_cast<uint64_t>(sources[i].grid.cols * sources[i].grid.rows);
    if (conditioning[i].noDataSamples == samples) {
      warnings.push_back(sources[i].argument +
                         ": every sample is no data, its water code: tiled as sea");
    }
  }
}

// The merge's heights at and below the shard level: the fragments the shards sampled, each
// position in a shard unit required to be there.
std::function<Result<PrecomputedSamples>(const formats::PackId&, SampleTable&)> shardSamples(
    const TilerOptions& options, const std::vector<formats::PackId>& units, uint32_t shardLevel) {
  return [&options, &units, shardLevel](const formats::PackId& id,
                                        SampleTable& table) -> Result<PrecomputedSamples> {
    if (auto read = readSampleFragments(options.outputDir, id,
                                        positionsPerTile(options.verticesPerSide), table);
        !read) {
      return Error{read.error()};
    }
    PrecomputedSamples heights;
    heights.table = &table;
    heights.mustHold = [&options, &units, shardLevel](const SamplePosition& p) {
      return std::binary_search(
          units.begin(), units.end(),
          packHolding(p.longitudeDegrees, p.latitudeDegrees, shardLevel, options.packTilesPerSide));
    };
    return heights;
  };
}

// The manifest's entry for a level: its packs, their index sizes (all or none), tiles, bounds
// and height range.
formats::LevelInfo levelInfo(uint32_t level, const std::vector<formats::PackId>& packs,
                             const std::vector<PackSummary>& summaries) {
  formats::LevelInfo info;
  info.level = level;
  info.packs = packs;
  for (const PackSummary& s : summaries) info.packIndexBytes.push_back(s.indexBytes);
  if (std::find(info.packIndexBytes.begin(), info.packIndexBytes.end(), 0u) !=
      info.packIndexBytes.end()) {
    info.packIndexBytes.clear();
  }
  info.bounds = {180, 90, -180, -90};
  info.heightRange = {INT16_MAX, INT16_MIN};
  for (const PackSummary& s : summaries) {
    info.tileCount += s.tiles;
    info.bounds = {
        std::min(info.bounds.west, s.bounds.west), std::min(info.bounds.south, s.bounds.south),
        std::max(info.bounds.east, s.bounds.east), std::max(info.bounds.north, s.bounds.north)};
    info.heightRange.include(s.range);
  }
  return info;
}

// Which packs of a level this run builds: all (one machine), those of the shard's units at and
// below the shard level (a shard), those above it (the merge).
std::vector<formats::PackId> packsOfRun(const TilerOptions& options, const TilingPlan& plan,
                                        uint32_t level, uint32_t shardLevel,
                                        const ShardPartition* partition) {
  if (options.role == TilerRole::Whole) return plan.packs(level);
  if (options.role == TilerRole::Merge) {
    return level < shardLevel ? plan.packs(level) : std::vector<formats::PackId>{};
  }
  std::vector<formats::PackId> packs;
  if (level < shardLevel) return packs;
  const auto& units = partition->units[options.shardIndex];
  for (const formats::PackId& pack : plan.packs(level)) {
    if (std::binary_search(units.begin(), units.end(), packAncestor(pack, shardLevel))) {
      packs.push_back(pack);
    }
  }
  return packs;
}

}  // namespace

Result<TilerReport> runTiler(const TilerOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (auto checked = checkOptions(options); !checked) return Error{checked.error()};
  TilerReport report;
  auto opened =
      openSources(options.inputs, {options.verticesPerSide, options.maxLevel, options.vertical,
                                   options.noDataIsSea, options.allowImages});
  if (!opened) return Error{opened.error()};
  std::vector<TilerSource>& allSources = *opened;
  warnOfKeptUnits(options, allSources, report.warnings);
  const TilingPlan plan = planOfSources(allSources, options.packTilesPerSide);
  const std::string fingerprint = planFingerprint(options, allSources);
  if (auto prepared = prepareOutput(options, fingerprint); !prepared) {
    return Error{prepared.error()};
  }

  // Shards and merge: the shard level, the units, and the sources this run reads.
  uint32_t shardLevel = 0;
  std::optional<ShardPartition> partition;
  std::vector<ShardSummary> shardSummaries;
  if (options.role == TilerRole::Shard) {
    auto level = chooseShardLevel(options.shardLevel, plan.maxLevel());
    if (!level) return Error{level.error()};
    shardLevel = *level;
    partition =
        partitionShards(plan, shardLevel, options.shardCount, allSources, options.packTilesPerSide);
  } else if (options.role == TilerRole::Merge) {
    std::error_code error;
    if (!fs::exists(shardFolder(options.outputDir), error) &&
        fs::exists(options.outputDir / formats::kManifestFileName, error)) {
      // A merge run again (a requeued job): it finished, and removed what the shards left.
      report.alreadyMerged = true;
      return report;
    }
    auto summaries = readShardSummaries(options.outputDir, fingerprint);
    if (!summaries) return Error{summaries.error()};
    shardSummaries = std::move(*summaries);
    shardLevel = shardSummaries.front().level;
  }
  const std::vector<size_t> used =
      sourcesOfRole(options, plan, allSources, partition ? &*partition : nullptr, shardLevel);
  std::vector<formats::SourceInfo> sourceInfos;
  for (const TilerSource& s : allSources) sourceInfos.push_back(s.info());
  std::vector<TilerSource> sources;
  for (size_t i : used) {
    sources.push_back(std::move(allSources[i]));
    report.sourceBytes +=
        static_cast<uint64_t>(sources.back().grid.cols * sources.back().grid.rows * 2);
  }
  report.sourcesConditioned = sources.size();

  const unsigned threads =
      options.threads != 0 ? options.threads : std::max(1U, std::thread::hardware_concurrency());
  ConditioningOptions conditioningOptions;
  conditioningOptions.threads = threads;
  conditioningOptions.spillDirectory = options.outputDir;
  auto conditioning = conditionSources(sources, conditioningOptions);
  if (!conditioning) return Error{conditioning.error()};
  warnOfAllSea(sources, *conditioning, report.warnings);
  // Each source's conditioning by its index among all, from this run or (merge) a shard.
  std::map<size_t, formats::SourceConditioning> conditioningOf;
  for (size_t i = 0; i < used.size(); ++i) conditioningOf[used[i]] = (*conditioning)[i];
  std::map<formats::PackId, PackSummary> shardPacks;
  for (const ShardSummary& shard : shardSummaries) {
    for (const auto& [source, c] : shard.conditioning) conditioningOf.emplace(source, c);
    for (const auto& [id, summary] : shard.packs) shardPacks.emplace(id, summary);
  }

  const auto packsToBuild = [&](uint32_t level) {
    return packsOfRun(options, plan, level, shardLevel, partition ? &*partition : nullptr);
  };
  uint64_t totalTiles = 0;
  for (uint32_t level = 0; level <= plan.maxLevel(); ++level) {
    for (const formats::PackId& pack : packsToBuild(level)) {
      totalTiles += plan.tilesInPack(pack).size();
    }
  }
  const formats::PackLayout layout{options.packTilesPerSide, options.verticesPerSide};
  PackJob job{options, layout, plan, sources, nullptr};
  if (options.role == TilerRole::Merge) {
    job.precomputed = shardSamples(options, plan.packs(shardLevel), shardLevel);
  }

  formats::PyramidManifest manifest;
  manifest.verticesPerSide = options.verticesPerSide;
  manifest.packTilesPerSide = options.packTilesPerSide;
  manifest.globeModel = options.globeModel;
  manifest.levels.resize(plan.maxLevel() + 1);

  std::atomic<uint64_t> tilesDone{0};
  std::vector<std::pair<formats::PackId, PackSummary>> builtSummaries;
  for (uint32_t level = plan.maxLevel() + 1; level-- > 0;) {
    const std::vector<formats::PackId> packs = packsToBuild(level);
    std::vector<PackSummary> summaries(packs.size());
    std::atomic<size_t> next{0};
    std::atomic<bool> failed{false};
    std::mutex mutex;
    std::condition_variable finished;
    std::string firstError;
    unsigned running = 0;
    std::vector<std::thread> workers;
    const unsigned workerCount = static_cast<unsigned>(std::min<size_t>(threads, packs.size()));
    for (unsigned w = 0; w < workerCount; ++w) {
      {
        std::lock_guard lock(mutex);
        ++running;
      }
      workers.emplace_back([&] {
        PackBuildStats stats;
        uint64_t built = 0, reused = 0;
        for (size_t i; !failed && (i = next++) < packs.size();) {
          bool wasReused = false;
          auto summary = job.run(packs[i], wasReused, stats);
          if (!summary) {
            std::lock_guard lock(mutex);
            if (!failed.exchange(true)) firstError = summary.error();
            break;
          }
          summaries[i] = *summary;
          (wasReused ? reused : built) += 1;
          tilesDone += summary->tiles;
        }
        std::lock_guard lock(mutex);
        report.packsBuilt += built;
        report.packsReused += reused;
        report.sampledVertices += stats.sampledVertices;
        --running;
        finished.notify_all();
      });
    }
    waitForLevel(options.progress, mutex, finished, running, tilesDone, totalTiles, level,
                 plan.maxLevel());
    for (std::thread& worker : workers) worker.join();
    if (failed) return makeError(firstError);
    for (size_t i = 0; i < packs.size(); ++i) {
      builtSummaries.emplace_back(packs[i], summaries[i]);
      report.tiles += summaries[i].tiles;  // the tiles of the packs this run built or reused
    }
    if (options.role == TilerRole::Merge && level >= shardLevel) {
      // The shards built these: their summaries stand for the packs.
      for (const formats::PackId& id : plan.packs(level)) {
        const auto found = shardPacks.find(id);
        if (found == shardPacks.end()) {
          return makeError("pack " + std::to_string(id.level) + "/" + std::to_string(id.x) + "/" +
                           std::to_string(id.y) + ": no shard built it");
        }
        summaries.push_back(found->second);
      }
    }

    manifest.levels[level] = levelInfo(level, plan.packs(level), summaries);
  }
  if (options.progress) options.progress({tilesDone, totalTiles, "done", true});

  if (options.role == TilerRole::Shard) {
    auto samples = writeShardSamples(options.outputDir, plan, partition->units[options.shardIndex],
                                     options.shardIndex, sources, options.verticesPerSide,
                                     options.packTilesPerSide);
    if (!samples) return Error{samples.error()};
    report.fragments = samples->fragments;
    ShardSummary summary{options.shardIndex, options.shardCount,        shardLevel,
                         fingerprint,        std::move(builtSummaries), {}};
    for (const auto& [source, c] : conditioningOf) summary.conditioning.emplace_back(source, c);
    // Written last: it says the shard is complete.
    if (auto written = writeShardSummary(options.outputDir, summary); !written) {
      return Error{written.error()};
    }
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
  }

  for (size_t i = 0; i < sourceInfos.size(); ++i) {
    const auto found = conditioningOf.find(i);
    if (found == conditioningOf.end()) {
      return makeError(sourceInfos[i].path + ": no shard conditioned it (a shard's summary lost?)");
    }
    manifest.sources.push_back(sourceInfos[i]);
    manifest.sources.back().conditioning = found->second;
  }
  if (auto written = transport::writeFileAtomically(options.outputDir / formats::kManifestFileName,
                                                    formats::manifestToJson(manifest));
      !written) {
    return writeFailed(written.error());
  }
  if (options.role == TilerRole::Merge) {
    std::error_code error;
    fs::remove_all(shardFolder(options.outputDir), error);
    if (error) {
      return makeError(shardFolder(options.outputDir).string() +
                       ": cannot remove: " + error.message());
    }
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace globe::tiling
