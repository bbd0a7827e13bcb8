#include "tiling/tiler.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>

#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "formats/vertical_units.hpp"
#include "geo/tiling_scheme.hpp"
#include "tiling/pack_builder.hpp"
#include "tiling/progress.hpp"
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

// What the manifest needs from one finished pack.
struct PackSummary {
  uint64_t tiles = 0;
  formats::BoundsDegrees bounds{180, 90, -180, -90};
  terrain::HeightRange range{INT16_MAX, INT16_MIN};
  uint32_t indexBytes = 0;  // the pack's stored index (version 5), for the manifest
};

PackSummary summarise(const formats::Pack& pack) {
  PackSummary summary;
  for (size_t slot = 0; slot < pack.entries.size(); ++slot) {
    const formats::PackEntry& entry = pack.entries[slot];
    if (!entry.present()) continue;
    ++summary.tiles;
    const auto rect = geo::GeographicTilingScheme::tileRectangle(
        formats::tileOfSlot(pack.id, slot, pack.layout.tilesPerSide));
    const double toDegrees = 180.0 / 3.14159265358979323846;
    summary.bounds.west = std::min(summary.bounds.west, rect.westRadians * toDegrees);
    summary.bounds.south = std::min(summary.bounds.south, rect.southRadians * toDegrees);
    summary.bounds.east = std::max(summary.bounds.east, rect.eastRadians * toDegrees);
    summary.bounds.north = std::max(summary.bounds.north, rect.northRadians * toDegrees);
    summary.range.include(entry.vertexRange);
  }
  return summary;
}

// Everything that decides the pyramid's content: a resumed run must match it exactly.
std::string planFingerprint(const TilerOptions& options, const std::vector<TilerSource>& sources) {
  nlohmann::json inputs = nlohmann::json::array();
  for (const TilerSource& s : sources) {
    std::error_code error;
    const auto bytes = fs::file_size(s.raster->path(), error);
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
  transport::removeAtomicTemporaries(options.outputDir);  // a killed run's half-written files
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
    auto pack = buildPack(id, layout, plan, sources, children,
                          geo::ellipsoidFor(options.globeModel), stats);
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

}  // namespace

Result<TilerReport> runTiler(const TilerOptions& options) {
  const auto start = std::chrono::steady_clock::now();
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
  TilerReport report;
  auto opened = openSources(options.inputs, {options.verticesPerSide, options.maxLevel,
                                             options.vertical, options.noDataIsSea});
  if (!opened) return Error{opened.error()};
  std::vector<TilerSource>& sources = *opened;
  if (options.vertical.units || options.vertical.metersPerUnit) {
    for (const TilerSource& s : sources) {
      const formats::VerticalUnitOrigin origin = s.verticalUnits.origin;
      if (origin != formats::VerticalUnitOrigin::File &&
          origin != formats::VerticalUnitOrigin::Format) {
        continue;
      }
      report.warnings.push_back(s.argument + ": keeps its own unit (" +
                                formats::describe(s.verticalUnits) +
                                "): --z-units / --z-scale apply to inputs that state none");
    }
  }
  std::vector<formats::BoundsDegrees> extents;
  std::vector<uint32_t> finestLevels;
  for (const TilerSource& s : sources) {
    extents.push_back(s.extent);
    finestLevels.push_back(s.finestLevel);
    report.sourceBytes += static_cast<uint64_t>(s.grid.cols * s.grid.rows * 2);
  }
  const TilingPlan plan(extents, finestLevels, options.packTilesPerSide);
  if (auto prepared = prepareOutput(options, planFingerprint(options, sources)); !prepared) {
    return Error{prepared.error()};
  }
  const unsigned threads =
      options.threads != 0 ? options.threads : std::max(1U, std::thread::hardware_concurrency());
  ConditioningOptions conditioningOptions;
  conditioningOptions.threads = threads;
  conditioningOptions.spillDirectory = options.outputDir;
  auto conditioning = conditionSources(sources, conditioningOptions);
  if (!conditioning) return Error{conditioning.error()};
  for (size_t i = 0; i < sources.size(); ++i) {
    const formats::SourceConditioning& c = (*conditioning)[i];
    if (c.noDataSamples == static_cast<uint64_t>(sources[i].grid.cols * sources[i].grid.rows)) {
      // Only a source whose no data is its water code gets here (others are refused).
      report.warnings.push_back(sources[i].argument +
                                ": every sample is no data, its water code: tiled as sea");
    }
  }

  uint64_t totalTiles = 0;
  for (uint32_t level = 0; level <= plan.maxLevel(); ++level) totalTiles += plan.tileCount(level);
  const formats::PackLayout layout{options.packTilesPerSide, options.verticesPerSide};
  const PackJob job{options, layout, plan, sources};

  formats::PyramidManifest manifest;
  manifest.verticesPerSide = options.verticesPerSide;
  manifest.packTilesPerSide = options.packTilesPerSide;
  manifest.globeModel = options.globeModel;
  manifest.levels.resize(plan.maxLevel() + 1);
  for (size_t i = 0; i < sources.size(); ++i) {
    manifest.sources.push_back(sources[i].info());
    manifest.sources.back().conditioning = (*conditioning)[i];
  }

  std::atomic<uint64_t> tilesDone{0};
  for (uint32_t level = plan.maxLevel() + 1; level-- > 0;) {
    const std::vector<formats::PackId>& packs = plan.packs(level);
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

    formats::LevelInfo& info = manifest.levels[level];
    info.level = level;
    info.packs = packs;
    info.packIndexBytes.clear();
    for (const PackSummary& s : summaries) info.packIndexBytes.push_back(s.indexBytes);
    if (std::find(info.packIndexBytes.begin(), info.packIndexBytes.end(), 0u) !=
        info.packIndexBytes.end()) {
      info.packIndexBytes.clear();  // all or none
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
    report.tiles += info.tileCount;
  }
  if (options.progress) options.progress({tilesDone, totalTiles, "done", true});
  if (auto written = transport::writeFileAtomically(options.outputDir / formats::kManifestFileName,
                                                    formats::manifestToJson(manifest));
      !written) {
    return writeFailed(written.error());
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace globe::tiling
