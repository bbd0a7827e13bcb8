#include "apps/globe-tiler/commands.hpp"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "apps/globe-tiler/progress_bar.hpp"
#include "apps/globe-tiler/shard_argument.hpp"
#include "geo/ellipsoid.hpp"
#include "globe_version.hpp"
#include "tiling/shard_report.hpp"
#include "tiling/tiler.hpp"

namespace globe::tiler_app {

namespace {

// --inputs FILE: one input a line; blank lines and lines starting with # are skipped.
bool readInputList(const std::string& path, std::vector<std::string>& inputs) {
  std::ifstream file(path);
  if (!file) {
    std::fprintf(stderr, "globe-tiler: --inputs %s: cannot read it\n", path.c_str());
    return false;
  }
  for (std::string line; std::getline(file, line);) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const auto last = line.find_last_not_of(" \t\r");
    inputs.push_back(line.substr(first, last - first + 1));
  }
  if (file.bad()) {
    std::fprintf(stderr, "globe-tiler: --inputs %s: read failed\n", path.c_str());
    return false;
  }
  return true;
}

int printShardPlan(const tiling::TilerOptions& options, double tilesPerSecond) {
  auto plan = tiling::planShards(options);
  if (!plan) {
    std::fprintf(stderr, "globe-tiler: %s\n", plan.error().c_str());
    return 1;
  }
  std::printf("%u shards of the packs at level %u (deepest level %u, %llu tiles in all)\n",
              options.shardCount, plan->shardLevel, plan->maxLevel,
              static_cast<unsigned long long>(plan->wholeTiles));
  std::printf("%-7s %8s %12s %8s %14s %14s\n", "shard", "units", "tiles", "sources", "source MB",
              "expected");
  auto row = [&](const std::string& name, const tiling::ShardPlanRow& r) {
    const double seconds = static_cast<double>(r.tiles) / tilesPerSecond;
    std::printf("%-7s %8llu %12llu %8llu %14.1f %14s\n", name.c_str(),
                static_cast<unsigned long long>(r.units), static_cast<unsigned long long>(r.tiles),
                static_cast<unsigned long long>(r.sources),
                static_cast<double>(r.sourceBytes) / 1e6, formatDuration(seconds).c_str());
  };
  for (size_t k = 0; k < plan->shards.size(); ++k) {
    row(std::to_string(k) + "/" + std::to_string(options.shardCount), plan->shards[k]);
  }
  row("merge", plan->merge);
  std::printf(
      "expected: at %.0f tiles per second per shard (--tiles-per-second), before the "
      "time to condition the sources\n",
      tilesPerSecond);
  return 0;
}

}  // namespace

int runTileCommand(int argc, char** argv, TileCommandKind kind) {
  CLI::App app{
      "Builds a tile pyramid (lat/long quadtree of N×N GTOPO30-encoded blocks) from GTOPO30 "
      ".DEM/.HDR files or any raster GDAL opens.\nAlso: globe-tiler export PYRAMID L X Y "
      "OUT_STEM\n      "
      "globe-tiler export --format quantized-mesh|heightmap|terrarium|terrain-rgb -o DIR PYRAMID "
      "(for CesiumJS, MapLibre)\n      "
      "globe-tiler imagery -o LAYER_DIR INPUT... (imagery layers; see globe-tiler imagery --help)\n"
      "      globe-tiler export-imagery --format xyz|tms|pmtiles -o OUT LAYER_DIR (for web maps)\n"
      "      globe-tiler water-mask -o LAYER_DIR POLYGONS... (water masks from land polygons)\n"
      "      globe-tiler buildings -o DIR FOOTPRINTS... --pyramid PYRAMID (3D Tiles buildings)\n"
      "      globe-tiler plan --shards N INPUT... (how the work splits; then on many machines "
      "globe-tiler --shard K/N -o OUT INPUT...)\n"
      "      globe-tiler merge -o OUT INPUT... (after the shards)",
      "globe-tiler"};
  app.set_version_flag("--version",
                       std::string("globe-tiler ") + kVersion + " (" + sourceRevision() + ")");
  tiling::TilerOptions options;
  std::string output, globeName = "wgs84";
  uint32_t maxLevel = 0;
  auto* outputOption =
      app.add_option("-o,--output", output, "pyramid directory to create (or resume)");
  if (kind != TileCommandKind::Plan) outputOption->required();
  app.add_option("INPUT", options.inputs,
                 "elevation rasters (paths, /vsicurl/ URLs); the finest wins where they overlap");
  std::string inputList;
  app.add_option("--inputs", inputList, "a file listing more inputs, one a line (# comments)");
  std::string shard;
  uint32_t shardLevel = 0, shardCount = 0;
  double tilesPerSecond = kMeasuredTilesPerSecond;
  CLI::Option* shardLevelOption = nullptr;
  if (kind == TileCommandKind::Tile) {
    app.add_option("--shard", shard,
                   "K/N: build shard K of N (from 0) into the shared output; then globe-tiler "
                   "merge");
  }
  if (kind != TileCommandKind::Merge) {
    shardLevelOption =
        app.add_option("--shard-level", shardLevel,
                       "level whose packs are cut into shards (default: three above the deepest)");
  }
  if (kind == TileCommandKind::Plan) {
    app.add_option("--shards", shardCount, "how many shards")->required();
    app.add_option("--tiles-per-second", tilesPerSecond,
                   "one shard's tiling rate, for the expected times")
        ->capture_default_str();
  }
  app.add_option("-n,--block-size", options.verticesPerSide, "vertices per block side, 2^k+1")
      ->capture_default_str();
  auto* maxLevelOption = app.add_option("--max-level", maxLevel,
                                        "deepest level (default: from each input's resolution)");
  app.add_option("--pack-tiles", options.packTilesPerSide, "tiles per pack file side")
      ->capture_default_str();
  app.add_option("-j,--threads", options.threads, "worker threads (default: every core)");
  app.add_option("--globe", globeName, "globe model recorded in the manifest: wgs84 | sphere")
      ->capture_default_str();
  std::string zUnits;
  double zScale = 1;
  auto* zUnitsOption = app.add_option(
      "--z-units", zUnits,
      "m | ft | us-ft: the heights' unit of the inputs that state none (GDAL unit type; none "
      "= m; an unknown one is an error); a stated unit, and GTOPO30's metres, are kept. Band "
      "scale/offset still apply");
  auto* zScaleOption = app.add_option("--z-scale", zScale,
                                      "metres per stored unit (after the band's scale/offset) of "
                                      "the inputs that state no unit")
                           ->excludes(zUnitsOption);
  app.add_flag("--no-data-is-sea", options.noDataIsSea,
               "every input's no data is water (an explicit water code), not missing data");
  app.add_flag("--force", options.allowImages,
               "tile an 8-bit colour or paletted image's band 1 as heights (refused otherwise: "
               "such a file is a layer for globe-tiler imagery)");
  bool quiet = false;
  app.add_flag("-q,--quiet", quiet, "no progress bar");
  app.footer(
      "How inputs are drawn:\n"
      "  - The finest input covering a point wins and is drawn as it is inside its footprint "
      "(where "
      "it has data).\n"
      "  - Sea only where something says sea: a measured height <= 0 m connected to open water; an "
      "explicit water code (GTOPO30's own 30\" grids, whose -9999 is the ocean mask, or any "
      "input's no data with --no-data-is-sea); or a coarser input's surface there at or below "
      "0 m. No data is never sea by connectivity alone.\n"
      "  - No data reaching a raster's border (reprojection wedges, a blanked part, clipped "
      "corners) is outside its footprint: coarser inputs show through. No data enclosed by data "
      "is a void, filled (from a coarser input's shape where one covers it); with no coarser "
      "input every void is filled.\n"
      "  - Outside a finer input, coarser ones bend to meet its edge over 1.5 of their own cells: "
      "no wall, no moat; finer land meeting coarser water becomes a shore sloping into it.\n"
      "  - Heights: the GDAL unit type (m, ft, US survey foot) and band scale/offset are applied; "
      "--z-units/--z-scale give the unit of inputs that state none; an unknown unit is an "
      "error.\n"
      "  - A raster with fewer than 2x2 valid samples is refused.");
  CLI11_PARSE(app, argc, argv);
  if (!inputList.empty() && !readInputList(inputList, options.inputs)) return 2;
  if (options.inputs.empty()) {
    std::fprintf(stderr, "globe-tiler: no inputs: give rasters or --inputs FILE\n");
    return 2;
  }
  if (!shard.empty()) {
    auto spec = parseShardSpec(shard);
    if (!spec) {
      std::fprintf(stderr, "globe-tiler: %s\n", spec.error().c_str());
      return 2;
    }
    options.role = tiling::TilerRole::Shard;
    options.shardIndex = spec->index;
    options.shardCount = spec->count;
  }
  if (kind == TileCommandKind::Merge) options.role = tiling::TilerRole::Merge;
  if (shardLevelOption != nullptr && shardLevelOption->count() > 0) options.shardLevel = shardLevel;
  if (zUnitsOption->count() > 0) options.vertical.units = zUnits;
  if (zScaleOption->count() > 0) options.vertical.metersPerUnit = zScale;

  options.outputDir = output;
  ProgressBar bar(!quiet && ::isatty(STDERR_FILENO) != 0);
  options.progress = bar.sink();
  if (maxLevelOption->count() > 0) options.maxLevel = maxLevel;
  const auto model = geo::parseGlobeModel(globeName);
  if (!model) {
    std::fprintf(stderr, "globe-tiler: --globe must be wgs84 or sphere, not '%s'\n",
                 globeName.c_str());
    return 2;
  }
  options.globeModel = *model;
  if (kind == TileCommandKind::Plan) {
    options.shardCount = shardCount;
    if (!(tilesPerSecond > 0)) {
      std::fprintf(stderr, "globe-tiler: --tiles-per-second must be above 0\n");
      return 2;
    }
    return printShardPlan(options, tilesPerSecond);
  }

  auto report = tiling::runTiler(options);
  if (!report) {
    std::fprintf(stderr, "globe-tiler: %s\n", report.error().c_str());
    return 1;
  }
  for (const std::string& warning : report->warnings) {
    std::fprintf(stderr, "globe-tiler: warning: %s\n", warning.c_str());
  }
  if (options.role == tiling::TilerRole::Shard) {
    std::printf(
        "%s: shard %u/%u: %llu tiles (%llu packs built, %llu reused), %llu sources "
        "read, %llu height fragments for the merge, in %s\n",
        output.c_str(), options.shardIndex, options.shardCount,
        static_cast<unsigned long long>(report->tiles),
        static_cast<unsigned long long>(report->packsBuilt),
        static_cast<unsigned long long>(report->packsReused),
        static_cast<unsigned long long>(report->sourcesConditioned),
        static_cast<unsigned long long>(report->fragments),
        formatDuration(report->seconds).c_str());
    return 0;
  }
  if (report->alreadyMerged) {
    std::printf("%s: already merged (its manifest is written and no shard is left)\n",
                output.c_str());
    return 0;
  }
  if (options.role == tiling::TilerRole::Merge) {
    std::printf(
        "%s: merged: %llu tiles above the shard level (%llu packs), %llu sources read, in "
        "%s; manifest written\n",
        output.c_str(), static_cast<unsigned long long>(report->tiles),
        static_cast<unsigned long long>(report->packsBuilt + report->packsReused),
        static_cast<unsigned long long>(report->sourcesConditioned),
        formatDuration(report->seconds).c_str());
    return 0;
  }
  const double mb = static_cast<double>(report->sourceBytes) / 1e6;
  std::printf(
      "%s: %llu tiles (%llu packs built, %llu reused) in %s; %.1f MB of source at %.1f MB/s, %.0f "
      "tiles/s\n",
      output.c_str(), static_cast<unsigned long long>(report->tiles),
      static_cast<unsigned long long>(report->packsBuilt),
      static_cast<unsigned long long>(report->packsReused), formatDuration(report->seconds).c_str(),
      mb, report->seconds > 0 ? mb / report->seconds : 0.0,
      report->seconds > 0 ? static_cast<double>(report->tiles) / report->seconds : 0.0);
  return 0;
}

}  // namespace globe::tiler_app
