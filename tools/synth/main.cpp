// globe-synth-gtopo30: writes a synthetic, world-sized GTOPO30 data set in the real product's
// layout (33 tiles: 27 of 40°×50° and 6 Antarctic ones of 60°×30°, 30″, 43200×21600 samples in
// all, 1.87 GB) so the tiler can be measured at full scale without downloading GTOPO30.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "rasters/gtopo30.hpp"

namespace {

struct TileSpec {
  int westDegrees, northDegrees, widthDegrees, heightDegrees;
};

std::vector<TileSpec> gtopo30Layout() {
  std::vector<TileSpec> tiles;
  for (int north : {90, 40, -10}) {
    for (int west = -180; west < 180; west += 40) tiles.push_back({west, north, 40, 50});
  }
  for (int west = -180; west < 180; west += 60) tiles.push_back({west, -60, 60, 30});
  return tiles;
}

std::string tileName(const TileSpec& t) {
  char name[32];
  std::snprintf(name, sizeof name, "%c%03d%c%02d", t.westDegrees < 0 ? 'W' : 'E',
                std::abs(t.westDegrees), t.northDegrees < 0 ? 'S' : 'N', std::abs(t.northDegrees));
  return name;
}

// Smooth continents and ridges from a few octaves of sines: deterministic and cheap.
int16_t syntheticHeight(double lonRadians, double latRadians) {
  double h = 1800 * std::sin(2 * lonRadians + 0.5) * std::cos(3 * latRadians) +
             900 * std::sin(7 * lonRadians + 1.3 * std::sin(5 * latRadians)) +
             350 * std::sin(23 * lonRadians) * std::sin(19 * latRadians) +
             120 * std::sin(97 * lonRadians + 3) * std::cos(89 * latRadians) - 300;
  if (h < 0) return -9999;  // GTOPO30 marks the sea as no data
  return static_cast<int16_t>(std::lround(std::min(h, 8800.0)));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes a synthetic world-sized GTOPO30 data set (33 tiles, 1.87 GB)"};
  std::string outDir;
  int stride = 1;
  app.add_option("-o,--output", outDir, "directory for the .DEM/.HDR files")->required();
  app.add_option("--decimate", stride,
                 "write every Nth sample only (a smaller set for quick runs)");
  CLI11_PARSE(app, argc, argv);
  std::filesystem::create_directories(outDir);
  const double step = 1.0 / 120 * stride;
  for (const TileSpec& t : gtopo30Layout()) {
    globe::rasters::Gtopo30Raster raster;
    auto& h = raster.header;
    h.cols = std::lround(t.widthDegrees / step);
    h.rows = std::lround(t.heightDegrees / step);
    h.bandRowBytes = h.totalRowBytes = h.cols * 2;
    h.xDimDegrees = h.yDimDegrees = step;
    h.ulxMapDegrees = t.westDegrees + step / 2;
    h.ulyMapDegrees = t.northDegrees - step / 2;
    raster.heights.resize(static_cast<size_t>(h.rows * h.cols));
    const double toRadians = std::numbers::pi / 180;
    for (int64_t r = 0; r < h.rows; ++r) {
      const double lat = (h.ulyMapDegrees - static_cast<double>(r) * step) * toRadians;
      for (int64_t c = 0; c < h.cols; ++c) {
        const double lon = (h.ulxMapDegrees + static_cast<double>(c) * step) * toRadians;
        raster.heights[static_cast<size_t>(r * h.cols + c)] = syntheticHeight(lon, lat);
      }
    }
    const auto stem = std::filesystem::path(outDir) / tileName(t);
    if (auto written = globe::rasters::writeGtopo30(stem, raster); !written) {
      std::fprintf(stderr, "globe-synth-gtopo30: %s\n", written.error().c_str());
      return 1;
    }
    std::printf("%s.DEM  %lldx%lld\n", stem.c_str(), static_cast<long long>(h.cols),
                static_cast<long long>(h.rows));
  }
  return 0;
}
