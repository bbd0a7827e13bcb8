#include "imagery_tiling/imagery_tiler.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "core/crc32.hpp"
#include "formats/image_pack.hpp"
#include "formats/layer_manifest.hpp"
#include "formats/pyramid_manifest.hpp"
#include "imagery_tiling/footprint_fade.hpp"
#include "imagery_tiling/imagery_pixels.hpp"
#include "imagery_tiling/imagery_plan.hpp"
#include "imagery_tiling/imagery_reader.hpp"
#include "imagery_tiling/reader_cache.hpp"
#include "tiling/progress.hpp"
#include "tiling/write_failed.hpp"
#include "transport/atomic_file.hpp"

namespace globe::imagery_tiling {
namespace {

namespace fs = std::filesystem;
constexpr const char* kImageryPlanFileName = "imagery-plan.json";
constexpr uint64_t kMaxImagePackBytes = uint64_t{1} << 34;
// Names the sampling and compositing rules: a layer resumed under other rules would mix them.
// Version 1: pixel-is-area tiles (a layer re-packing a TMS tree keeps them); 2: edge samples.
constexpr const char* kRulesVersion = "bilinear-premultiplied-finest-over 1";
constexpr const char* kEdgeSampledRulesVersion =
    "bilinear-premultiplied-finest-over 2 edges (exact in JPEG), footprints and no-data collars "
    "fade over 4 pixels";

std::string boundsText(const formats::BoundsDegrees& b) {
  char text[128];
  std::snprintf(text, sizeof text, "%.17g,%.17g,%.17g,%.17g", b.west, b.south, b.east, b.north);
  return text;
}

// Everything that decides the layer's bytes: a resumed run must match it exactly.
std::string planFingerprint(const ImageryTilerOptions& options,
                            const std::vector<ImageryInput>& inputs) {
  nlohmann::json list = nlohmann::json::array();
  for (const ImageryInput& input : inputs) {
    std::error_code error;
    const auto bytes = fs::is_regular_file(input.argument, error)
                           ? fs::file_size(input.argument, error)
                           : uintmax_t{0};
    list.push_back({{"path", input.argument},
                    {"bytes", error ? 0 : bytes},
                    {"columns", input.info.columns},
                    {"rows", input.info.rows},
                    {"boundsDegrees", boundsText(input.extent)},
                    {"wrappedBoundsDegrees",
                     input.wrappedExtent ? boundsText(*input.wrappedExtent) : std::string()},
                    {"finestLevel", input.finestLevel},
                    {"bands", input.info.bands},
                    {"stretch", input.info.stretch}});
  }
  const nlohmann::json plan = {
      {"inputs", list},
      {"packTilesPerSide", options.packTilesPerSide},
      {"jpegQuality", options.jpegQuality},
      {"rules", inputs.empty() || inputs[0].pixelGrid == formats::ImageryPixelGrid::Area
                    ? kRulesVersion
                    : kEdgeSampledRulesVersion}};
  return plan.dump(1) + "\n";
}

Result<void> prepareOutput(const fs::path& dir, const std::string& fingerprint) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) return makeError(dir.string() + ": cannot create: " + error.message());
  transport::removeAtomicTemporaries(dir);  // a killed run's half-written files
  if (fs::exists(dir / formats::kManifestFileName, error)) {
    return makeError(dir.string() + ": holds a terrain pyramid; choose another output directory");
  }
  const fs::path planPath = dir / kImageryPlanFileName;
  if (fs::exists(planPath, error)) {
    auto existing = transport::readWholeFile(planPath, 1 << 24);
    if (!existing) return Error{existing.error()};
    if (std::string(reinterpret_cast<const char*>(existing->data()), existing->size()) !=
        fingerprint) {
      return makeError(dir.string() +
                       ": holds a layer made from other inputs or options; remove it or choose "
                       "another output directory");
    }
    return {};
  }
  if (fs::exists(dir / formats::kLayerManifestFileName, error)) {
    return makeError(dir.string() + ": holds a layer without " + kImageryPlanFileName +
                     "; remove it or choose another output directory");
  }
  if (auto written = transport::writeFileAtomically(planPath, fingerprint); !written) {
    return tiling::writeFailed(written.error());
  }
  return {};
}

Result<formats::ImagePack> readImagePack(const fs::path& path) {
  auto bytes = transport::readWholeFile(path, kMaxImagePackBytes);
  if (!bytes) return Error{bytes.error()};
  return formats::decodeImagePack(*bytes, path);
}

// What the manifest needs from one finished pack.
struct ImagePackSummary {
  uint64_t tiles = 0;         // tiles holding pixels
  uint64_t plannedTiles = 0;  // for a pack kept from an earlier run: the tiles it stands for
  formats::BoundsDegrees bounds{180, 90, -180, -90};
};

void include(formats::BoundsDegrees& bounds, const formats::BoundsDegrees& more) {
  bounds = {std::min(bounds.west, more.west), std::min(bounds.south, more.south),
            std::max(bounds.east, more.east), std::max(bounds.north, more.north)};
}

ImagePackSummary summarise(const formats::ImagePackIndex& index) {
  ImagePackSummary summary;  // of a reused pack
  for (size_t slot = 0; slot < index.entries.size(); ++slot) {
    if (!index.entries[slot].present()) continue;
    ++summary.tiles;
    const TileFrameDegrees f =
        tileFrameDegrees(formats::tileOfSlot(index.id, slot, index.tilesPerSide));
    include(summary.bounds, {f.west, f.north - f.size, f.west + f.size, f.north});
  }
  return summary;
}

// The finished packs of the level below, read whole and kept a while: a tile's four children
// usually share one pack.
class ChildTiles {
 public:
  ChildTiles(fs::path dir, uint32_t tilesPerSide, size_t capacity)
      : dir_(std::move(dir)), tilesPerSide_(tilesPerSide), capacity_(capacity) {}

  Result<std::optional<formats::ImageRgba>> load(const geo::TileId& tile) {
    const formats::PackId id = formats::packOf(tile, tilesPerSide_);
    std::shared_ptr<const formats::ImagePack> pack;
    {
      std::lock_guard lock(mutex_);
      if (auto it = packs_.find(id); it != packs_.end()) {
        pack = it->second;
      } else {
        auto read = readImagePack(formats::packPath(dir_, id));
        if (!read) return Error{read.error()};
        if (packs_.size() >= capacity_) packs_.clear();
        pack = std::make_shared<const formats::ImagePack>(std::move(*read));
        packs_.emplace(id, pack);
      }
    }
    const size_t slot = formats::slotOf(tile, tilesPerSide_);
    if (pack->payloads[slot].empty()) return std::optional<formats::ImageRgba>();
    auto image =
        formats::decodeImageRgba(pack->payloads[slot], formats::packPath(dir_, id).string() +
                                                           " slot " + std::to_string(slot));
    if (!image) return Error{image.error()};
    return std::optional<formats::ImageRgba>(std::move(*image));
  }

 private:
  fs::path dir_;
  uint32_t tilesPerSide_;
  size_t capacity_;
  std::mutex mutex_;
  std::map<formats::PackId, std::shared_ptr<const formats::ImagePack>> packs_;
};

struct TileMaker {
  const std::vector<ImageryInput>& inputs;
  const std::vector<size_t>& finestFirst;  // input indices, finest pixel first
  const ImageryPlan& plan;
  int jpegQuality;

  // The tile's encoded bytes, or nullopt when no input covers any of its pixels.
  Result<std::optional<std::vector<std::byte>>> make(const geo::TileId& tile, ReaderCache& readers,
                                                     ChildTiles* children, bool& copied) const {
    copied = false;
    const TileFrameDegrees frame = tileFrameDegrees(tile);
    std::vector<size_t> over;
    for (size_t i : finestFirst) {
      if (overlapsFootprint(inputs[i], frame.west, frame.north - frame.size,
                            frame.west + frame.size, frame.north)) {
        over.push_back(i);
      }
    }
    // A TMS tree alone under this tile: its own tile, byte for byte.
    if (over.size() == 1 && inputs[over[0]].kind == ImageryInput::Kind::Tms &&
        tile.level <= inputs[over[0]].tmsMaxLevel) {
      auto reader = readers.get(over[0]);
      if (!reader) return Error{reader.error()};
      copied = true;
      return (*reader)->ownTile(tile);
    }
    formats::ImageRgba image = transparentTile();
    if (children != nullptr) {
      std::array<std::optional<formats::ImageRgba>, 4> quadrants;
      bool any = false;
      const auto ids = tile.children();
      for (size_t q = 0; q < 4; ++q) {
        if (!plan.planned(ids[q])) continue;
        auto child = children->load(ids[q]);
        if (!child) return Error{child.error()};
        quadrants[q] = std::move(*child);
        any = any || quadrants[q].has_value();
      }
      if (any) {
        image = inputs.empty() || inputs[0].pixelGrid == formats::ImageryPixelGrid::Area
                    ? averageChildren(quadrants)
                    : downsampleEdgeSampledChildren(quadrants);
      }
    }
    // Inputs whose finest level is this one or coarser paint here, finest first, each under
    // what is already there; finer inputs came in through the children.
    bool covered = anyCovered(image);
    formats::ImageRgba layer;
    for (size_t i : over) {
      if (inputs[i].finestLevel > tile.level) continue;
      if (covered && fullyOpaque(image)) break;
      auto reader = readers.get(i);
      if (!reader) return Error{reader.error()};
      if (!covered) {  // nothing yet to composite under: draw straight into the tile
        auto drawn = (*reader)->render(tile, image);
        if (!drawn) return Error{drawn.error()};
        covered = *drawn;
        continue;
      }
      layer = transparentTile();
      auto drawn = (*reader)->render(tile, layer);
      if (!drawn) return Error{drawn.error()};
      if (*drawn) compositeOver(image, layer);
    }
    if (!covered) return std::optional<std::vector<std::byte>>();
    // Edge-sampled JPEG tiles keep their border exactly (formats/tile_edges.hpp).
    auto encoded =
        encodeTile(image, jpegQuality,
                   !inputs.empty() && inputs[0].pixelGrid == formats::ImageryPixelGrid::Edges);
    if (!encoded) return Error{encoded.error()};
    return std::optional<std::vector<std::byte>>(std::move(*encoded));
  }
};

// A pack being built: its tiles' payloads fill in from any worker; the last one writes it.
struct PackWork {
  formats::PackId id;
  std::vector<geo::TileId> tiles;
  std::vector<std::vector<std::byte>> payloads;
  std::atomic<size_t> remaining{0};
  size_t summaryIndex = 0;
};

Result<void> checkOptions(const ImageryTilerOptions& options) {
  if (options.inputs.empty()) return makeError("no input given");
  if (options.jpegQuality < 1 || options.jpegQuality > 100) {
    return makeError("--quality must be between 1 and 100");
  }
  if (options.packTilesPerSide == 0 ||
      options.packTilesPerSide > formats::kImagePackMaxTilesPerSide) {
    return makeError("--pack-tiles must be between 1 and " +
                     std::to_string(formats::kImagePackMaxTilesPerSide));
  }
  if (options.input.maxLevel && *options.input.maxLevel > geo::kMaxLevel) {
    return makeError("--max-level must be at most " + std::to_string(geo::kMaxLevel));
  }
  return {};
}

// The level's packs still to build. A complete pack from an interrupted run is kept: its
// summary (with its planned tiles, counted as done) goes into `summaries`; a damaged or foreign
// file is rebuilt.
std::vector<std::unique_ptr<PackWork>> packsToBuild(const ImageryPlan& plan, uint32_t level,
                                                    const fs::path& outputDir,
                                                    uint32_t tilesPerSide,
                                                    std::vector<ImagePackSummary>& summaries,
                                                    ImageryTilerReport& report) {
  const std::vector<formats::PackId>& packs = plan.packs(level);
  std::vector<std::unique_ptr<PackWork>> work;
  for (size_t i = 0; i < packs.size(); ++i) {
    const fs::path path = formats::packPath(outputDir, packs[i]);
    std::error_code error;
    if (fs::exists(path, error)) {
      auto existing = readImagePack(path);
      if (existing && existing->index.id == packs[i] &&
          existing->index.tilesPerSide == tilesPerSide) {
        summaries[i] = summarise(existing->index);
        summaries[i].plannedTiles = plan.tilesInPack(packs[i]).size();
        ++report.packsReused;
        continue;
      }
    }
    auto pack = std::make_unique<PackWork>();
    pack->id = packs[i];
    pack->tiles = plan.tilesInPack(packs[i]);
    pack->payloads.resize(size_t{tilesPerSide} * tilesPerSide);
    pack->remaining = pack->tiles.size();
    pack->summaryIndex = i;
    work.push_back(std::move(pack));
  }
  return work;
}

// The manifest's entry for a level: its packs, tiles and the bounds of those that hold pixels.
formats::ImageryLevelInfo levelInfo(uint32_t level, const std::vector<formats::PackId>& packs,
                                    const std::vector<ImagePackSummary>& summaries) {
  formats::ImageryLevelInfo info;
  info.level = level;
  info.packs = packs;
  info.bounds = {180, 90, -180, -90};
  for (const ImagePackSummary& s : summaries) {
    info.tileCount += s.tiles;
    include(info.bounds, s.bounds);
  }
  if (info.tileCount == 0) info.bounds = {};
  return info;
}

}  // namespace

Result<ImageryTilerReport> runImageryTiler(const ImageryTilerOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (auto checked = checkOptions(options); !checked) return Error{checked.error()};
  auto described = describeImageryInputs(options.inputs, options.input);
  if (!described) return Error{described.error()};
  // Samples at the tiles' edges (no colour step between tiles), unless a TMS tree's own
  // pixel-is-area tiles are re-packed into the layer.
  const bool anyTms = std::any_of(described->begin(), described->end(), [](const ImageryInput& i) {
    return i.kind == ImageryInput::Kind::Tms;
  });
  const formats::ImageryPixelGrid pixelGrid =
      anyTms ? formats::ImageryPixelGrid::Area : formats::ImageryPixelGrid::Edges;
  for (ImageryInput& input : *described) input.pixelGrid = pixelGrid;
  chooseFootprintFades(*described);
  const std::vector<ImageryInput>& inputs = *described;
  std::vector<formats::BoundsDegrees> extents;
  std::vector<uint32_t> finestLevels;
  std::vector<size_t> finestFirst;
  for (size_t i = 0; i < inputs.size(); ++i) {
    extents.push_back(inputs[i].extent);
    finestLevels.push_back(inputs[i].finestLevel);
    if (inputs[i].wrappedExtent) {
      extents.push_back(*inputs[i].wrappedExtent);
      finestLevels.push_back(inputs[i].finestLevel);
    }
    finestFirst.push_back(i);
  }
  std::stable_sort(finestFirst.begin(), finestFirst.end(), [&](size_t a, size_t b) {
    return inputs[a].pixelDegrees < inputs[b].pixelDegrees;
  });
  const ImageryPlan plan(extents, finestLevels, options.packTilesPerSide);
  const std::string fingerprint = planFingerprint(options, inputs);
  if (auto prepared = prepareOutput(options.outputDir, fingerprint); !prepared) {
    return Error{prepared.error()};
  }
  const unsigned threads =
      options.threads != 0 ? options.threads : std::max(1U, std::thread::hardware_concurrency());
  std::vector<std::unique_ptr<ReaderCache>> readers;
  for (unsigned w = 0; w < threads; ++w) {
    readers.push_back(std::make_unique<ReaderCache>(inputs, readersPerWorker(threads)));
  }

  ImageryTilerReport report;
  report.maxLevel = plan.maxLevel();
  for (const ImageryInput& input : inputs) {
    report.warnings.insert(report.warnings.end(), input.warnings.begin(), input.warnings.end());
  }
  const TileMaker maker{inputs, finestFirst, plan, options.jpegQuality};
  formats::LayerManifest manifest;
  manifest.packTilesPerSide = options.packTilesPerSide;
  manifest.pixelGrid = pixelGrid;
  manifest.levels.resize(plan.maxLevel() + 1);
  manifest.bounds = {180, 90, -180, -90};
  for (const ImageryInput& input : inputs) manifest.sources.push_back(input.info);
  char fingerprintText[16];
  std::snprintf(fingerprintText, sizeof fingerprintText, "crc32:%08x",
                core::crc32(std::as_bytes(std::span(fingerprint))));
  manifest.planFingerprint = fingerprintText;

  std::atomic<uint64_t> tilesDone{0};
  for (uint32_t level = plan.maxLevel() + 1; level-- > 0;) {
    const std::vector<formats::PackId>& packs = plan.packs(level);
    std::vector<ImagePackSummary> summaries(packs.size());
    std::vector<std::unique_ptr<PackWork>> work =
        packsToBuild(plan, level, options.outputDir, options.packTilesPerSide, summaries, report);
    for (const ImagePackSummary& reused : summaries) tilesDone += reused.plannedTiles;
    std::vector<std::pair<size_t, size_t>> items;  // (pack, tile), packs in order
    for (size_t p = 0; p < work.size(); ++p) {
      for (size_t t = 0; t < work[p]->tiles.size(); ++t) items.emplace_back(p, t);
    }
    std::unique_ptr<ChildTiles> children;
    if (level < plan.maxLevel()) {
      children = std::make_unique<ChildTiles>(options.outputDir, options.packTilesPerSide,
                                              4 * size_t{threads} + 8);
    }
    std::atomic<size_t> next{0};
    std::atomic<bool> failed{false};
    std::mutex mutex;
    std::string firstError;
    unsigned running = 0;
    auto fail = [&](const std::string& message) {
      std::lock_guard lock(mutex);
      if (!failed.exchange(true)) firstError = message;
    };
    auto finishPack = [&](PackWork& pack) -> Result<void> {
      const fs::path path = formats::packPath(options.outputDir, pack.id);
      const auto bytes = formats::encodeImagePack(pack.id, options.packTilesPerSide, pack.payloads);
      std::error_code error;
      fs::create_directories(path.parent_path(), error);
      if (error) {
        return makeError(path.parent_path().string() + ": cannot create: " + error.message());
      }
      if (auto written = transport::writeFileAtomically(path, bytes); !written) {
        return tiling::writeFailed(written.error());
      }
      ImagePackSummary& summary = summaries[pack.summaryIndex];
      for (const geo::TileId& tile : pack.tiles) {
        if (pack.payloads[formats::slotOf(tile, options.packTilesPerSide)].empty()) continue;
        ++summary.tiles;
        const TileFrameDegrees f = tileFrameDegrees(tile);
        include(summary.bounds, {f.west, f.north - f.size, f.west + f.size, f.north});
      }
      pack.payloads = {};
      return {};
    };
    std::vector<std::thread> workers;
    std::atomic<uint64_t> built{0}, copied{0}, packsBuilt{0};
    const unsigned workerCount =
        static_cast<unsigned>(std::min<size_t>(threads, std::max<size_t>(items.size(), 1)));
    running = workerCount;
    std::condition_variable finished;
    for (unsigned w = 0; w < workerCount; ++w) {
      workers.emplace_back([&, w] {
        for (size_t i; !failed && (i = next++) < items.size();) {
          PackWork& pack = *work[items[i].first];
          const geo::TileId& tile = pack.tiles[items[i].second];
          bool wasCopied = false;
          auto made = maker.make(tile, *readers[w], children.get(), wasCopied);
          if (!made) {
            fail(made.error());
            break;
          }
          if (*made) {
            pack.payloads[formats::slotOf(tile, options.packTilesPerSide)] = std::move(**made);
            ++built;
            copied += wasCopied ? 1 : 0;
          }
          ++tilesDone;
          if (--pack.remaining == 0) {
            if (auto written = finishPack(pack); !written) {
              fail(written.error());
              break;
            }
            ++packsBuilt;
          }
        }
        std::lock_guard lock(mutex);
        --running;
        finished.notify_all();
      });
    }
    tiling::waitForLevel(options.progress, mutex, finished, running, tilesDone, plan.tileCount(),
                         level, plan.maxLevel());
    for (std::thread& worker : workers) worker.join();
    if (failed) return makeError(firstError);
    // A pack with no planned tile to render (all empty) is still written, for resuming.
    for (auto& pack : work) {
      if (pack->tiles.empty()) {
        if (auto written = finishPack(*pack); !written) return Error{written.error()};
        ++packsBuilt;
      }
    }
    report.tilesBuilt += built;
    report.tilesCopied += copied;
    report.packsBuilt += packsBuilt;

    manifest.levels[level] = levelInfo(level, packs, summaries);
    if (manifest.levels[level].tileCount != 0)
      include(manifest.bounds, manifest.levels[level].bounds);
    report.tiles += manifest.levels[level].tileCount;
  }
  if (options.progress) options.progress({tilesDone, plan.tileCount(), "done", true});
  if (manifest.tileCount() == 0) {
    return makeError("no input covers any pixel: nothing to tile");
  }
  if (auto written = formats::writeLayerManifest(options.outputDir, manifest); !written) {
    return tiling::writeFailed(written.error());
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace globe::imagery_tiling
