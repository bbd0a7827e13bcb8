#include "tests/support/tiler_test_fixture.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/crc32.hpp"
#include "terrain/height_block.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/shared_fixture.hpp"
#include "tiling/source_conditioning.hpp"
#include "tiling/source_set.hpp"
#include "tiling/tiler.hpp"
#include "transport/atomic_file.hpp"

namespace globe::testing {

std::vector<std::string> bundledInputs() {
  const std::string dir = std::string(GLOBE_SOURCE_DIR) + "/data/dem/";
  return {dir + "ETOPO20.DEM", dir + "W002N52.DEM", dir + "E138N35_FUJI.DEM"};
}

namespace {

// Every temporary directory a test process makes is removed when it exits.
struct TempDirs {
  std::vector<std::filesystem::path> dirs;
  ~TempDirs() {
    std::error_code ignored;
    for (const auto& dir : dirs) std::filesystem::remove_all(dir, ignored);
  }
};
TempDirs& tempDirs() {
  static TempDirs instance;
  return instance;
}

}  // namespace

std::filesystem::path freshTempDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("globe-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  tempDirs().dirs.push_back(dir);
  return dir;
}

const std::filesystem::path& bundledPyramid() {
  static const std::filesystem::path dir = sharedPyramid("bundled-pyramid", bundledInputs());
  return dir;
}

bool tilePyramidInto(const std::filesystem::path& out, const std::vector<std::string>& inputs) {
  tiling::TilerOptions options;
  options.inputs = inputs;
  options.outputDir = out;
  auto report = tiling::runTiler(options);
  if (!report) ADD_FAILURE() << report.error();
  return report.ok();
}

std::filesystem::path tilePyramid(const std::string& name, const std::vector<std::string>& inputs) {
  auto out = freshTempDir(name) / "pyramid";
  tilePyramidInto(out, inputs);
  return out;
}

std::filesystem::path sharedPyramid(const std::string& name,
                                    const std::vector<std::string>& inputs) {
  std::string key = "pyramid-" + name;
  for (const std::string& input : inputs) key += " " + input;
  return sharedFixture(
      key, [&](const std::filesystem::path& dir) { return tilePyramidInto(dir, inputs); });
}

std::map<std::string, std::pair<uint32_t, size_t>> checksums(const std::filesystem::path& dir) {
  std::map<std::string, std::pair<uint32_t, size_t>> sums;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    auto bytes = transport::readWholeFile(entry.path(), 1ULL << 32);
    EXPECT_TRUE(bytes) << bytes.error();
    if (bytes) {
      sums[std::filesystem::relative(entry.path(), dir).string()] = {core::crc32(*bytes),
                                                                     bytes->size()};
    }
  }
  return sums;
}

int16_t Oracle::Raster::sample(int64_t row, int64_t column) const {
  if (grid.wrapsLongitude) column = ((column % grid.cols) + grid.cols) % grid.cols;
  return samples[static_cast<size_t>(row * grid.cols + column)];
}

Oracle::Oracle(const std::vector<std::string>& inputs) {
  // The sources as the tiler conditions them (sea, voids, blend: tested in tests/dem); what this
  // oracle checks independently is the sampling of those samples into vertices.
  auto sources = tiling::openSources(inputs, {});
  if (!sources) {
    ADD_FAILURE() << sources.error();
    return;
  }
  if (auto conditioned = tiling::conditionSources(*sources); !conditioned) {
    ADD_FAILURE() << conditioned.error();
    return;
  }
  for (const tiling::TilerSource& source : *sources) {
    Raster r{source.raster->grid(), {}, 0, source.extent, source.bendMarginDegrees};
    r.step = std::min(r.grid.columnStepDegrees, r.grid.rowStepDegrees);
    r.samples.resize(static_cast<size_t>(r.grid.cols * r.grid.rows));
    for (int64_t row = 0; row < r.grid.rows; ++row) {
      auto read = source.raster->readRow(row, 0, r.grid.cols,
                                         &r.samples[static_cast<size_t>(row * r.grid.cols)]);
      if (!read) ADD_FAILURE() << read.error();
    }
    rasters_.push_back(std::move(r));
  }
}

int16_t Oracle::height(double lon, double lat) const {
  for (const Raster& r : rasters_) {
    const geo::SampleGrid& g = r.grid;
    const double south = g.southDegrees() < -90.0 + 1e-9 ? -90.0 : g.southDegrees();
    const double north = g.northDegrees() > 90.0 - 1e-9 ? 90.0 : g.northDegrees();
    if (lat < south || lat > north) continue;
    if (!g.wrapsLongitude && (lon < g.westDegrees() || lon > g.eastDegrees())) continue;
    const int16_t value = rasterHeight(r, lon, lat);
    // Near a finer raster's edge, outside it, the surface bends towards that edge (smoothstep):
    // land and sea floors alike; water where this raster is and the bent height is at most 0 m.
    const Raster* finer = nullptr;
    double weight = 0;
    for (const Raster& f : rasters_) {
      if (!(f.margin > 0) || f.grid.wrapsLongitude || !(f.step < r.step)) continue;
      const double dx = std::max({f.extent.west - lon, 0.0, lon - f.extent.east});
      const double dy = std::max({f.extent.south - lat, 0.0, lat - f.extent.north});
      const double d = std::hypot(dx, dy);
      if (d <= 0 || d >= f.margin) continue;
      const double t = d / f.margin;
      const double w = 1.0 - t * t * (3.0 - 2.0 * t);
      if (w > weight) weight = w, finer = &f;
    }
    if (finer == nullptr) return value;
    const double here = terrain::seaFloorMeters(value);
    const double mixed = here + weight * (edgeMeters(*finer, lon, lat) - here);
    if (terrain::isWater(value) && mixed <= 0.0) {
      return mixed < -0.5 ? terrain::encodeWater(mixed) : int16_t{-9999};
    }
    const double land = terrain::isWater(value) ? mixed : std::max(mixed, std::min(0.0, here));
    const auto rounded = static_cast<int16_t>(std::clamp(std::lround(land), -12000L, 32767L));
    return rounded == -9999 ? int16_t{-10000} : rounded;
  }
  return -9999;
}

// The finer raster's edge as the ground outside bends to it: at distance d beyond a side, the
// mean of that side's linear height profile over d each way along it (clipped to the side);
// beyond a corner, both sides' means weighted by how far the point lies beyond each.
double Oracle::edgeMeters(const Raster& r, double lon, double lat) const {
  const geo::SampleGrid& g = r.grid;
  const double dx = std::max({r.extent.west - lon, 0.0, lon - r.extent.east});
  const double dy = std::max({r.extent.south - lat, 0.0, lat - r.extent.north});
  const double d = std::hypot(dx, dy);
  // Mean of the profile f(0..n-1) (linear between samples) over [centre - half, centre + half].
  auto mean = [](const std::function<double(int64_t)>& f, int64_t n, double centre, double half) {
    const double last = static_cast<double>(n - 1);
    const double a = std::clamp(centre - half, 0.0, last), b = std::clamp(centre + half, 0.0, last);
    auto at = [&](double x) {
      const auto i = std::min(static_cast<int64_t>(std::floor(x)), n - 1);
      const double t = x - static_cast<double>(i);
      return i + 1 < n ? f(i) * (1 - t) + f(i + 1) * t : f(i);
    };
    if (b - a < 1e-3) return at(std::clamp(centre, 0.0, last));
    // Exact integral of the piecewise-linear profile: trapezoids between the breakpoints.
    double sum = 0, x = a;
    while (x < b) {
      const double next = std::min(b, std::floor(x) + 1);
      sum += (next - x) * (at(x) + at(next)) / 2;
      x = next;
    }
    return sum / (b - a);
  };
  const double column = (lon - g.firstColumnLongitudeDegrees) / g.columnStepDegrees;
  const double row = (g.firstRowLatitudeDegrees - lat) / g.rowStepDegrees;
  const int64_t sideColumn = lon < r.extent.west ? 0 : g.cols - 1;
  const int64_t sideRow = lat > r.extent.north ? 0 : g.rows - 1;
  const double beside =
      mean([&](int64_t i) { return terrain::seaFloorMeters(r.sample(i, sideColumn)); }, g.rows, row,
           d / g.rowStepDegrees);
  const double beyond =
      mean([&](int64_t i) { return terrain::seaFloorMeters(r.sample(sideRow, i)); }, g.cols, column,
           d / g.columnStepDegrees);
  if (dx <= 0) return beyond;
  if (dy <= 0) return beside;
  return (dx * beside + dy * beyond) / (dx + dy);
}

int16_t Oracle::rasterHeight(const Raster& r, double lon, double lat) const {
  {
    const geo::SampleGrid& g = r.grid;
    if (std::abs(lat) == 90.0) {  // the pole: highest sample of the polar row
      const int64_t row = lat > 0 ? 0 : g.rows - 1;
      int16_t bestLand = 0, bestWater = INT16_MIN;
      bool anyLand = false;
      for (int64_t c = 0; c < g.cols; ++c) {
        const int16_t s = r.sample(row, c);
        if (terrain::isWater(s)) {
          bestWater = std::max(bestWater, s);
        } else {
          bestLand = anyLand ? std::max(bestLand, s) : s, anyLand = true;
        }
      }
      return anyLand ? bestLand : bestWater;
    }
    // The same arithmetic as the tiler: a vertex halfway between samples is a rounding tie.
    double offset = lon - g.firstColumnLongitudeDegrees;
    if (g.wrapsLongitude) offset -= 360.0 * std::floor(offset / 360.0);
    double u = offset / g.columnStepDegrees;
    if (!g.wrapsLongitude) u = std::clamp(u, 0.0, static_cast<double>(g.cols - 1));
    const double v = std::clamp((g.firstRowLatitudeDegrees - lat) / g.rowStepDegrees, 0.0,
                                static_cast<double>(g.rows - 1));
    const auto c0 = static_cast<int64_t>(std::floor(u));
    const auto r0 = static_cast<int64_t>(std::floor(v));
    const int64_t c1 = g.wrapsLongitude ? c0 + 1 : std::min(c0 + 1, g.cols - 1);
    const int64_t r1 = std::min(r0 + 1, g.rows - 1);
    const double tu = u - static_cast<double>(c0), tv = v - static_cast<double>(r0);
    const int16_t nearest = r.sample(tv < 0.5 ? r0 : r1, tu < 0.5 ? c0 : c1);
    const int16_t corners[4] = {r.sample(r0, c0), r.sample(r0, c1), r.sample(r1, c0),
                                r.sample(r1, c1)};
    int water = 0, measured = 0;
    for (int16_t s : corners) {
      water += terrain::isWater(s) ? 1 : 0;
      measured += terrain::isWater(s) && s != -9999 ? 1 : 0;
    }
    // Land and sea floor together (floor 0 m where unknown), or water at 0 m.
    auto mix = [&](bool floors) {
      auto h = [&](int k) {
        const int16_t s = corners[k];
        return !terrain::isWater(s) ? double(s) : floors ? terrain::seaFloorMeters(s) : 0.0;
      };
      // The tiler's arithmetic order, so rounding ties round alike.
      return (1 - tv) * ((1 - tu) * h(0) + tu * h(1)) + tv * ((1 - tu) * h(2) + tu * h(3));
    };
    bool isWaterVertex = terrain::isWater(nearest);
    double value = mix(false);
    if (water == 4) {
      isWaterVertex = true, value = mix(true);
    } else if (water > 0 && measured > 0) {
      value = mix(true);
      isWaterVertex = value < 0;
    } else if (water == 0) {
      isWaterVertex = false;
    }
    if (isWaterVertex) return value < -0.5 ? terrain::encodeWater(value) : int16_t{-9999};
    const auto rounded = static_cast<int16_t>(std::lround(value));
    return rounded == -9999 ? int16_t{-10000} : rounded;
  }
}

}  // namespace globe::testing
