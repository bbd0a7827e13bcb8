// globe-bench-fill: cuts holes of several sizes into the valid land of real tiles, fills them with
// dem::fillVoids (with and without a coarser source) and with GDAL's GDALFillNodata, and reports
// RMSE, p99 and max error against the removed truth (docs/performance/fill-accuracy.md).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "conditioning/condition.hpp"
#include "conditioning/grid_coarser_sources.hpp"
#include "tests/support/build_paths.hpp"
#include "tiling/dem_reader.hpp"
#include "tools/bench_fill/block_average.hpp"
#include "tools/bench_fill/fill_benchmark.hpp"
#include "tools/bench_fill/gdal_fill.hpp"
#include "tools/bench_fill/report.hpp"
#include "transport/atomic_file.hpp"

namespace {

using namespace globe;
using namespace globe::bench_fill;

const std::string kInterpolation = "globe, interpolation";
const std::string kHarmonic = "globe, harmonic only";
const std::string kEtopo = "globe + ETOPO20";
const std::string kSrtm30 = "globe + SRTM30-like";
const std::string kGdal = "GDAL";
const std::string kGdalSmoothed = "GDAL si=2";

constexpr double kKilometresPerDegree = 111.32;  // north-south, near enough for a table
constexpr int64_t kSrtm30Factor = 10;            // 3″ → 30″

const std::map<std::string, std::string> kDescriptions = {
    {"N50E008", "Taunus / Hesse (SRTM3), hills and the Rhine–Main plain"},
    {"W002N52", "eastern England (GTOPO30), low relief, North Sea coast"},
    {"N57E011", "Kattegat coast (SRTM3), mostly sea at 0 m; holes on the land part"},
};

// Size classes: nominal diameter in samples and how many holes of it per tile.
const std::vector<HoleClass> kHoleClasses = {{3, 100}, {8, 50},  {20, 16},
                                             {50, 8},  {120, 4}, {300, 3}};

std::string commandLine(int argc, char** argv) {
  std::string line = "globe-bench-fill";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    line += arg.find_first_of(" \t'\"") == std::string::npos ? " " + arg : " '" + arg + "'";
  }
  return line;
}

// A 3″ SRTM tile (its 30″ block means are SRTM30-like).
bool isSrtm3(const conditioning::DemGrid& grid) {
  return std::abs(grid.columnStepDegrees * 3600 - 3) < 1e-6 && (grid.cols - 1) % kSrtm30Factor == 0;
}

// The classes whose blobs (at most 1.3 × the diameter across) fit the tile at all (W002N52 is
// only 240 samples wide).
std::vector<HoleClass> classesThatFit(const conditioning::DemGrid& grid,
                                      const HolePlacement& placement) {
  std::vector<HoleClass> fitting;
  for (const HoleClass& c : kHoleClasses) {
    const double span =
        1.3 * c.diameterSamples + 2.0 * static_cast<double>(placement.edgeMarginSamples) + 4;
    if (span < static_cast<double>(std::min(grid.rows, grid.cols))) fitting.push_back(c);
  }
  return fitting;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Fill accuracy of dem::fillVoids against GDALFillNodata on holes cut into real "
      "real tiles."};
  const std::string source = GLOBE_SOURCE_DIR;
  std::vector<std::string> tiles = {source + "/tests/data/dem/gtopo30/N50E008.DEM",
                                    source + "/data/dem/W002N52.DEM",
                                    source + "/tests/data/dem/gtopo30/N57E011.DEM"};
  std::string etopoPath = source + "/data/dem/ETOPO20.DEM";
  std::string outPath;
  BenchOptions options;
  options.placement.seed = 20240611;
  GdalFillOptions gdal;
  app.add_option("--tile", tiles, "tiles to cut holes into (GTOPO30 or any GDAL raster)")
      ->capture_default_str();
  app.add_option("--etopo", etopoPath, "the 20′ whole-globe coarser source")->capture_default_str();
  app.add_option("--out", outPath, "also write the markdown report to this file");
  app.add_option("--seed", options.placement.seed, "hole placement seed")->capture_default_str();
  app.add_option("--repeats", options.repeats, "runs per method and class (median time)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--gdal-max-search", gdal.maxSearchDistancePixels,
                 "GDALFillNodata max search distance, pixels")
      ->capture_default_str();
  app.add_option("--small-void-max", options.fill.smallVoidMaxSamples,
                 "FillOptions::smallVoidMaxSamples")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  const auto start = std::chrono::steady_clock::now();

  auto etopo = tiling::readDemGrid(etopoPath);
  if (!etopo) {
    std::fprintf(stderr, "globe-bench-fill: %s\n", etopo.error().c_str());
    return 1;
  }
  // Conditioned as the tiler conditions its coarsest source: the sea (negative depths connected
  // to open sea) becomes water, which the coarser surface takes at 0 m.
  conditioning::conditionGrid(*etopo, nullptr, {});
  const conditioning::GridCoarserSources etopoSource({&*etopo});

  ReportInput report;
  report.commandLine = commandLine(argc, argv);
  report.gdalVersion = gdalVersion();
  report.options = options;
  report.gdalMaxSearchDistancePixels = gdal.maxSearchDistancePixels;
  report.methodLabels = {kInterpolation, kHarmonic, kEtopo, kSrtm30, kGdal, kGdalSmoothed};
  report.gdalReferenceLabel = kGdal;
  report.interpolationLabel = kInterpolation;
  report.hardwareThreads = std::thread::hardware_concurrency();
  report.coarserNote =
      "- **globe + ETOPO20**: the coarser source is ETOPO20 (data/dem, 20′, NOAA's ETOPO5-derived "
      "relief): a real, independent measurement, conditioned with `dem::conditionGrid` like the "
      "tiler's coarsest input and answered by `dem::GridCoarserSources` (bilinear, water at "
      "0 m).\n"
      "- **globe + SRTM30-like** (3″ tiles only): the coarser source is a 30″ grid made from the "
      "tile's own 3″ samples (area means over 30″ cells on whole-degree lines, rounded), which is "
      "how SRTM30 is derived from SRTM3, conditioned over ETOPO20 likewise. It is made from the "
      "whole tile, so it holds the "
      "removed truth itself: **optimistic**, an upper bound of what a real 30″ source gives.\n";

  for (const std::string& path : tiles) {
    auto truth = tiling::readDemGrid(path);
    if (!truth) {
      std::fprintf(stderr, "globe-bench-fill: %s\n", truth.error().c_str());
      return 1;
    }
    TileReport tile;
    tile.name = std::filesystem::path(path).stem().string();
    if (auto known = kDescriptions.find(tile.name); known != kDescriptions.end()) {
      tile.description = known->second;
    }
    tile.cols = truth->cols;
    tile.rows = truth->rows;
    tile.stepArcSeconds = std::round(truth->rowStepDegrees * 3600 * 1000) / 1000;
    tile.rowStepKilometres = truth->rowStepDegrees * kKilometresPerDegree;
    for (int16_t h : truth->samples) {
      tile.landSamples += isLand(h);
      tile.noDataSamples += h == -9999;
    }

    conditioning::DemGrid srtm30Grid;
    std::unique_ptr<conditioning::GridCoarserSources> srtm30;
    std::vector<FillMethod> methods = {{kInterpolation, FillMethod::Kind::Globe, nullptr, {}},
                                       {kHarmonic, FillMethod::Kind::Globe, nullptr, {}, true},
                                       {kEtopo, FillMethod::Kind::Globe, &etopoSource, {}}};
    if (isSrtm3(*truth)) {
      srtm30Grid = blockAverage(*truth, kSrtm30Factor);
      conditioning::conditionGrid(srtm30Grid, &etopoSource, {});
      srtm30 = std::make_unique<conditioning::GridCoarserSources>(
          std::vector{&std::as_const(srtm30Grid)});
      methods.push_back({kSrtm30, FillMethod::Kind::Globe, srtm30.get(), {}});
    }
    GdalFillOptions smoothed = gdal;
    smoothed.smoothingIterations = 2;
    methods.push_back({kGdal, FillMethod::Kind::Gdal, nullptr, gdal});
    methods.push_back({kGdalSmoothed, FillMethod::Kind::Gdal, nullptr, smoothed});

    std::fprintf(stderr, "globe-bench-fill: %s ...\n", tile.name.c_str());
    auto classes =
        benchmarkTile(*truth, methods, classesThatFit(*truth, options.placement), options);
    if (!classes) {
      std::fprintf(stderr, "globe-bench-fill: %s: %s\n", path.c_str(), classes.error().c_str());
      return 1;
    }
    tile.classes = std::move(*classes);
    report.tiles.push_back(std::move(tile));
  }
  report.totalSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::string markdown = markdownReport(report);
  std::fputs(markdown.c_str(), stdout);
  if (!outPath.empty()) {
    if (auto written = transport::writeFileAtomically(outPath, markdown); !written) {
      std::fprintf(stderr, "globe-bench-fill: %s\n", written.error().c_str());
      return 1;
    }
  }
  return 0;
}
