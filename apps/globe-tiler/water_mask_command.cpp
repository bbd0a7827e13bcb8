#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>

#include "apps/globe-tiler/commands.hpp"
#include "apps/globe-tiler/progress_bar.hpp"
#include "mask_tiling/water_mask_tiler.hpp"

namespace globe::tiler_app {

int runWaterMaskCommand(int argc, char** argv) {
  CLI::App app{
      "Builds a water-mask layer: 256x256 tiles of the water fraction around each sample "
      "(antialiased coastlines), on the terrain's lat/long quadtree, in pack files, with "
      "layer.json. Give it to globe with --layer like an imagery layer: where the terrain's own "
      "sources are coarser than the mask, each pixel is drawn as land or water by the mask, so a "
      "coarse grid's coasts are drawn where the shoreline is.\n"
      "Inputs: vector files of land polygons that OGR opens (GeoPackage, FlatGeobuf, Shapefile, "
      "GeoJSON, ...), any CRS; every polygon layer, land being the even-odd fill of their rings "
      "(lakes as holes, islands in lakes as rings inside those). Where layers overlap, the one "
      "with the finest shoreline (shortest median edge) decides, blended into the coarser one "
      "near the sides of its extent; outside every layer's extent "
      "the terrain decides. tools/coastline/gshhg_land_polygons.py makes such a file from "
      "Debian's GSHHG shorelines.\n"
      "Levels: each layer down to the first level whose texel is at most half its median "
      "shoreline edge (at most 13), or --max-level. Tiles are split only where a shoreline runs "
      "through them.",
      "globe-tiler water-mask"};
  mask_tiling::WaterMaskTilerOptions options;
  std::string output;
  uint32_t maxLevel = 0;
  app.add_option("-o,--output", output, "layer directory to create (or replace a water mask in)")
      ->required();
  app.add_option("INPUT", options.inputs, "vector files of land polygons")->required();
  auto* maxLevelOption =
      app.add_option("--max-level", maxLevel, "deepest level for every layer (default: per layer)");
  app.add_option("--pack-tiles", options.packTilesPerSide, "tiles per pack file side")
      ->capture_default_str();
  app.add_option("-j,--threads", options.threads, "worker threads (default: every core)");
  bool quiet = false;
  app.add_flag("-q,--quiet", quiet, "no progress bar");
  CLI11_PARSE(app, argc, argv);

  options.outputDir = output;
  if (maxLevelOption->count() > 0) options.maxLevel = maxLevel;
  ProgressBar bar(!quiet && ::isatty(STDERR_FILENO) != 0);
  options.progress = bar.sink();
  auto report = mask_tiling::runWaterMaskTiler(options);
  if (!report) {
    std::fprintf(stderr, "globe-tiler water-mask: %s\n", report.error().c_str());
    return 1;
  }
  std::printf(
      "%s: %llu tiles, levels 0-%u (%llu on a shoreline), from %llu polygon layers (%llu rings, "
      "%llu vertices) in %s\n",
      output.c_str(), static_cast<unsigned long long>(report->tiles), report->maxLevel,
      static_cast<unsigned long long>(report->coastTiles),
      static_cast<unsigned long long>(report->layers),
      static_cast<unsigned long long>(report->rings),
      static_cast<unsigned long long>(report->vertices), formatDuration(report->seconds).c_str());
  return 0;
}

}  // namespace globe::tiler_app
