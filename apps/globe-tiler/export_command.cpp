#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <thread>

#include <unistd.h>

#include "apps/globe-tiler/commands.hpp"
#include "apps/globe-tiler/export_progress.hpp"
#include "geo/ellipsoid.hpp"
#include "publish/heightmap_export.hpp"
#include "publish/quantized_mesh_export.hpp"
#include "publish/terrarium_export.hpp"
#include "streaming/tile_store.hpp"
#include "tiling/export_block.hpp"

namespace globe::tiler_app {
namespace {

// The tile trees export writes, one row each: its --format name, whether its tiles may be
// lossless WebP, and the exporter. The option's choices, the --webp check and the dispatch all
// read this table (a name not in it is refused by the option, never exported as another).
struct ExportSettings {
  publish::ExportRegion region;
  geo::Ellipsoid ellipsoid = geo::Ellipsoid::wgs84();
  publish::ElevationTileFormat tiles = publish::ElevationTileFormat::Png;
  double meshErrorFraction = 1.0;
  publish::ExportWork work;
};
using Exporter = Result<publish::ExportReport> (*)(streaming::TerrainSource& store,
                                                   const std::string& out,
                                                   const ExportSettings& s);
struct TreeFormat {
  const char* name;
  bool webpTiles;
  Exporter run;
};
constexpr TreeFormat kTreeFormats[] = {
    {"quantized-mesh", false,
     [](streaming::TerrainSource& store, const std::string& out, const ExportSettings& s) {
       return publish::exportQuantizedMesh(store, s.region, out, s.ellipsoid, s.meshErrorFraction,
                                           s.work);
     }},
    {"heightmap", false,
     [](streaming::TerrainSource& store, const std::string& out, const ExportSettings& s) {
       return publish::exportHeightmap(store, s.region, out, s.ellipsoid, s.work);
     }},
    {"terrarium", true,
     [](streaming::TerrainSource& store, const std::string& out, const ExportSettings& s) {
       return publish::exportTerrarium(store, s.region, out, s.ellipsoid, s.tiles, s.work);
     }},
    {"terrain-rgb", true,
     [](streaming::TerrainSource& store, const std::string& out, const ExportSettings& s) {
       return publish::exportTerrainRgb(store, s.region, out, s.ellipsoid, s.tiles, s.work);
     }},
};

const TreeFormat* treeFormatNamed(const std::string& name) {
  for (const TreeFormat& f : kTreeFormats) {
    if (name == f.name) return &f;
  }
  return nullptr;
}

std::vector<std::string> treeFormatNames() {
  std::vector<std::string> names;
  for (const TreeFormat& f : kTreeFormats) names.emplace_back(f.name);
  return names;
}

// globe-tiler export --format F -o DIR PYRAMID: a tile tree for web viewers.
int exportTree(const std::string& format, const std::string& out, const std::string& pyramid,
               const std::string& levels, const std::string& bounds, bool webp,
               double meshErrorFraction, unsigned threads, bool quiet) {
  publish::ExportRegion region;
  if (!levels.empty() && !publish::parseExportLevels(levels, region)) {
    std::fprintf(stderr, "globe-tiler export: --levels must be A-B or A, not '%s'\n",
                 levels.c_str());
    return 2;
  }
  if (!bounds.empty() && !publish::parseExportBounds(bounds, region)) {
    std::fprintf(stderr,
                 "globe-tiler export: --bounds must be W,S,E,N in degrees (W < E, S < N), not "
                 "'%s'\n",
                 bounds.c_str());
    return 2;
  }
  auto store = streaming::TileStore::open(pyramid);
  if (!store) {
    std::fprintf(stderr, "globe-tiler export: %s\n", store.error().c_str());
    return 1;
  }
  const auto start = std::chrono::steady_clock::now();
  ExportSettings settings;
  settings.region = region;
  settings.tiles =
      webp ? publish::ElevationTileFormat::WebpLossless : publish::ElevationTileFormat::Png;
  settings.meshErrorFraction = meshErrorFraction;
  ExportProgressPrinter progress(format, threads, quiet, ::isatty(STDERR_FILENO) != 0);
  settings.work = {threads, progress.sink()};
  auto report = treeFormatNamed(format)->run(**store, out, settings);
  progress.finish();
  if (!report) {
    std::fprintf(stderr, "globe-tiler export: %s\n", report.error().c_str());
    return 1;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%s: %llu %s tiles written (%.1f MB), %llu kept from an earlier run, in %.1f s\n",
              out.c_str(), static_cast<unsigned long long>(report->tilesWritten), format.c_str(),
              static_cast<double>(report->bytesWritten) / 1e6,
              static_cast<unsigned long long>(report->tilesKept), seconds);
  return 0;
}

}  // namespace

int runExportCommand(int argc, char** argv) {
  CLI::App app{
      "Export a pyramid for other viewers: a tile tree (--format quantized-mesh or heightmap for "
      "CesiumJS, terrarium or terrain-rgb for MapLibre and others), or one block as a standalone "
      "GTOPO30 .DEM/.HDR",
      "globe-tiler export"};
  std::string format, out, levels, bounds;
  std::vector<std::string> positional;
  bool webp = false;
  double meshErrorFraction = 1.0;
  unsigned threads = std::max(1U, std::thread::hardware_concurrency());
  app.add_option("--format", format,
                 "quantized-mesh | heightmap | terrarium | terrain-rgb (a tile tree into -o DIR; "
                 "heightmap: Cesium's heightmap-1.0)")
      ->check(CLI::IsMember(treeFormatNames()));
  app.add_flag("--webp", webp,
               "terrarium, terrain-rgb: tiles as lossless WebP ({z}/{x}/{y}.webp) instead of PNG "
               "(always lossless: a lossy colour would be another height)");
  app.add_option("--mesh-error", meshErrorFraction,
                 "quantized-mesh: each tile's TIN lies within this fraction of the tile's "
                 "geometric error (CesiumJS's estimate, 77 km / 2^level, what it refines by) of "
                 "the surface; 0 keeps the whole 65×65 grid, the surface exactly (default 1)")
      ->check(CLI::Range(0.0, 16.0));
  app.add_option("-j,--threads", threads,
                 "worker threads making tiles (default: every core; the same bytes as one)")
      ->check(CLI::Range(1U, 1024U));
  app.add_option("-o,--output", out, "the tree's directory (with --format)");
  bool quiet = false;
  app.add_flag("-q,--quiet", quiet,
               "with --format: say nothing until the end (no tile count, expected time or bar)");
  app.add_option(
      "--levels", levels,
      "A-B: pyramid levels (quantized-mesh, heightmap) or Web-Mercator zooms (terrarium, "
      "terrain-rgb); default all (zooms: 0 to 22, as deep as the pyramid has data)");
  app.add_option("--bounds", bounds, "W,S,E,N degrees: the region exported (default the world)");
  app.add_option("ARGS", positional,
                 "with --format: PYRAMID; without: PYRAMID L X Y OUT_STEM (one block as GTOPO30 "
                 ".DEM .HDR .PRJ .STX)")
      ->required();
  CLI11_PARSE(app, argc, argv);
  if (!format.empty()) {
    if (out.empty() || positional.size() != 1) {
      std::fprintf(stderr, "globe-tiler export: --format needs -o DIR and one PYRAMID\n");
      return 2;
    }
    if (webp && !treeFormatNamed(format)->webpTiles) {
      std::fprintf(stderr,
                   "globe-tiler export: --webp is for --format terrarium or terrain-rgb "
                   "(lossless WebP elevation tiles), not '%s'\n",
                   format.c_str());
      return 2;
    }
    return exportTree(format, out, positional[0], levels, bounds, webp, meshErrorFraction, threads,
                      quiet);
  }
  if (webp) {
    std::fprintf(stderr, "globe-tiler export: --webp needs --format terrarium or terrain-rgb\n");
    return 2;
  }
  if (positional.size() != 5) {
    std::fprintf(stderr,
                 "globe-tiler export: PYRAMID L X Y OUT_STEM (one block), or --format F -o DIR "
                 "PYRAMID (a tile tree)\n");
    return 2;
  }
  uint32_t level = 0, x = 0, y = 0;
  try {
    level = static_cast<uint32_t>(std::stoul(positional[1]));
    x = static_cast<uint32_t>(std::stoul(positional[2]));
    y = static_cast<uint32_t>(std::stoul(positional[3]));
  } catch (const std::exception&) {
    std::fprintf(stderr, "globe-tiler export: L X Y must be whole numbers\n");
    return 2;
  }
  const std::string& pyramid = positional[0];
  const std::string& stem = positional[4];
  if (auto done = tiling::exportBlock(pyramid, {level, x, y}, stem); !done) {
    std::fprintf(stderr, "globe-tiler export: %s\n", done.error().c_str());
    return 1;
  }
  std::printf("wrote %s.DEM and %s.HDR (tile %u/%u/%u)\n", stem.c_str(), stem.c_str(), level, x, y);
  return 0;
}

}  // namespace globe::tiler_app
