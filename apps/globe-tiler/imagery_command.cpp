#include "apps/globe-tiler/commands.hpp"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "apps/globe-tiler/progress_bar.hpp"
#include "imagery_tiling/imagery_tiler.hpp"

namespace globe::tiler_app {
namespace {

// "a,b,c" → numbers, or nullopt when it is not exactly `count` finite numbers.
std::optional<std::vector<double>> parseNumbers(const std::string& text, size_t count) {
  std::vector<double> numbers;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ',')) {
    try {
      size_t used = 0;
      const double value = std::stod(part, &used);
      if (used != part.size() || !std::isfinite(value)) return std::nullopt;
      numbers.push_back(value);
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }
  if (numbers.size() != count) return std::nullopt;
  return numbers;
}

}  // namespace

int runImageryCommand(int argc, char** argv) {
  CLI::App app{
      "Builds an imagery layer: 256x256 JPEG/PNG tiles on the terrain's lat/long quadtree, in "
      "pack files, with layer.json.\n"
      "Inputs: any raster GDAL opens with colour (GeoTIFF in any CRS, JPEG/PNG with a world "
      "file, VRT mosaics) and TMS tile trees (a directory with tilemapresource.xml, geodetic, "
      "256 px). No data and masks become transparent. The finest input wins where inputs "
      "overlap; its transparent pixels let coarser ones show.\n"
      "Bands: --bands R,G,B[,A] when given; else GDAL's colour interpretation: red, green and "
      "blue in any band order (BGR files draw right), a palette expanded. Otherwise one band is "
      "grey (one of heights, signed or float samples or a unit of length, is an elevation model: "
      "refused without --force; one unsigned 16-bit band is drawn with a warning), and three or "
      "more draw their first three (alpha aside) as red, green, blue, with a warning naming "
      "them when the image has more. Alpha: the band GDAL calls alpha, or the A "
      "of --bands.\n"
      "Depth: 8-bit bands are drawn as they are; deeper ones (16-bit, float) are stretched per "
      "band from its 2nd to its 98th percentile (whole band, no data excluded) to 0..255, or by "
      "--scale MIN,MAX.\n"
      "Levels: each input down to the first level whose texel (tile width / 256) is no larger "
      "than its pixel after warping to longitude/latitude.",
      "globe-tiler imagery"};
  imagery_tiling::ImageryTilerOptions options;
  std::string output, bounds, bands, scale;
  uint32_t maxLevel = 0;
  app.add_option("-o,--output", output, "layer directory to create (or resume)")->required();
  app.add_option("INPUT", options.inputs, "rasters or TMS directories; the finest wins")
      ->required();
  auto* maxLevelOption =
      app.add_option("--max-level", maxLevel, "deepest level (default: from the finest input)");
  app.add_option("--bounds", bounds,
                 "W,S,E,N in degrees for the inputs without georeference (a plate carree image: "
                 "pixel-is-area, EPSG:4326); an error when every input is georeferenced");
  app.add_option("--bands", bands,
                 "R,G,B or R,G,B,A: 1-based band numbers drawn as red, green, blue (and alpha) "
                 "for every raster input, instead of their colour interpretation");
  app.add_option("--scale", scale,
                 "stretch for 16-bit/float inputs: MIN,MAX maps linearly to 0..255 (every band); "
                 "'auto' (the default) maps each band's 2-98 % percentiles");
  app.add_option("--quality", options.jpegQuality, "JPEG quality of opaque tiles (1..100)")
      ->capture_default_str();
  app.add_option("--pack-tiles", options.packTilesPerSide, "tiles per pack file side")
      ->capture_default_str();
  app.add_option("-j,--threads", options.threads, "worker threads (default: every core)");
  app.add_flag("--force", options.input.allowElevation,
               "draw one band of heights (signed or float samples, or a unit of length) as grey "
               "(refused otherwise: such a file is an elevation model, for globe-tiler -o PYRAMID)");
  bool quiet = false;
  app.add_flag("-q,--quiet", quiet, "no progress bar");
  CLI11_PARSE(app, argc, argv);

  options.outputDir = output;
  ProgressBar bar(!quiet && ::isatty(STDERR_FILENO) != 0);
  options.progress = bar.sink();
  if (maxLevelOption->count() > 0) options.input.maxLevel = maxLevel;
  if (!bounds.empty()) {
    const auto b = parseNumbers(bounds, 4);
    if (!b || (*b)[0] >= (*b)[2] || (*b)[1] >= (*b)[3] || (*b)[0] < -180 || (*b)[2] > 180 ||
        (*b)[1] < -90 || (*b)[3] > 90) {
      std::fprintf(stderr,
                   "globe-tiler imagery: --bounds must be W,S,E,N with W < E in -180..180 and "
                   "S < N in -90..90, not '%s'\n",
                   bounds.c_str());
      return 2;
    }
    options.input.bounds = formats::BoundsDegrees{(*b)[0], (*b)[1], (*b)[2], (*b)[3]};
  }
  if (!bands.empty()) {
    const auto numbers =
        parseNumbers(bands, static_cast<size_t>(std::count(bands.begin(), bands.end(), ',')) + 1);
    const bool valid = numbers && (numbers->size() == 3 || numbers->size() == 4) &&
                       std::all_of(numbers->begin(), numbers->end(), [](double n) {
                         return n >= 1 && n <= 65535 && n == std::floor(n);
                       });
    if (!valid) {
      std::fprintf(stderr,
                   "globe-tiler imagery: --bands must be R,G,B or R,G,B,A (1-based band numbers), "
                   "not '%s'\n",
                   bands.c_str());
      return 2;
    }
    for (double n : *numbers) options.input.bands.push_back(static_cast<int>(n));
  }
  if (scale == "auto") {
    options.input.scaleAuto = true;
  } else if (!scale.empty()) {
    const auto s = parseNumbers(scale, 2);
    if (!s || (*s)[0] >= (*s)[1]) {
      std::fprintf(stderr,
                   "globe-tiler imagery: --scale must be MIN,MAX with MIN < MAX, or auto, not "
                   "'%s'\n",
                   scale.c_str());
      return 2;
    }
    options.input.scale = imagery_tiling::ImageryStretch{(*s)[0], (*s)[1]};
  }
  auto report = imagery_tiling::runImageryTiler(options);
  if (!report) {
    std::fprintf(stderr, "globe-tiler imagery: %s\n", report.error().c_str());
    return 1;
  }
  for (const std::string& warning : report->warnings) {
    std::fprintf(stderr, "globe-tiler imagery: warning: %s\n", warning.c_str());
  }
  std::printf(
      "%s: %llu tiles, levels 0-%u (%llu tiles built, %llu re-packed from TMS; %llu packs "
      "built, %llu reused) in %s, %.0f tiles/s\n",
      output.c_str(), static_cast<unsigned long long>(report->tiles), report->maxLevel,
      static_cast<unsigned long long>(report->tilesBuilt),
      static_cast<unsigned long long>(report->tilesCopied),
      static_cast<unsigned long long>(report->packsBuilt),
      static_cast<unsigned long long>(report->packsReused), formatDuration(report->seconds).c_str(),
      report->seconds > 0 ? static_cast<double>(report->tilesBuilt) / report->seconds : 0.0);
  return 0;
}

}  // namespace globe::tiler_app
