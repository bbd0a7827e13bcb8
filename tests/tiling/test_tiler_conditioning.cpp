// Real data through the tiler's conditioning: the Fuji SRTM tile's voids, its sea (0 m) and its
// edges against the 20′ world grid, as the pyramid holds them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include "conditioning/grid_coarser_sources.hpp"
#include "conditioning/sea_classification.hpp"
#include "conditioning/void_fill.hpp"
#include "geo/tiling_scheme.hpp"
#include "rasters/gtopo30.hpp"
#include "streaming/tile_store.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/height_block.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "tiling/dem_reader.hpp"
#include "tiling/source_conditioning.hpp"
#include "tiling/tiler.hpp"

namespace globe::tiling {
namespace {

using globe::testing::bundledInputs;
using globe::testing::bundledPyramid;

const std::string kFuji = std::string(GLOBE_SOURCE_DIR) + "/data/dem/E138N35_FUJI.DEM";
const std::string kWorld = std::string(GLOBE_SOURCE_DIR) + "/data/dem/ETOPO20.DEM";
constexpr uint32_t kFujiLevel = 14;

// A source read into a dem grid, as given.
conditioning::DemGrid readRaw(const std::string& path) {
  auto grid = readDemGrid(path);
  EXPECT_TRUE(grid) << grid.error();
  return grid ? std::move(*grid) : conditioning::DemGrid{};
}

// The level-L vertex lattice of a pyramid over a window: heights by global vertex index.
struct Lattice {
  double spacingDegrees = 0;
  std::map<std::pair<int64_t, int64_t>, int16_t> samples;  // (global row, global column)
  std::optional<int16_t> at(int64_t row, int64_t column) const {
    auto it = samples.find({row, column});
    if (it == samples.end()) return std::nullopt;
    return it->second;
  }
  double longitude(int64_t column) const { return -180.0 + spacingDegrees * double(column); }
  double latitude(int64_t row) const { return 90.0 - spacingDegrees * double(row); }
};

Lattice readLattice(streaming::TileStore& store, uint32_t level, double west, double south,
                    double east, double north) {
  const uint32_t n = store.manifest().verticesPerSide;
  Lattice lattice;
  lattice.spacingDegrees = terrain::vertexSpacingDegrees(level, n);
  const double tileDegrees = 180.0 / double(1U << level);
  for (auto x = static_cast<uint32_t>((west + 180.0) / tileDegrees);
       double(x) * tileDegrees - 180.0 < east; ++x) {
    for (auto y = static_cast<uint32_t>((90.0 - north) / tileDegrees);
         90.0 - double(y) * tileDegrees > south; ++y) {
      const geo::TileId tile{level, x, y};
      auto block = store.loadBlock(tile);
      if (!block) continue;  // absent tiles: the lattice has a gap there
      for (uint32_t i = 0; i < n; ++i) {
        for (uint32_t j = 0; j < n; ++j) {
          lattice.samples[{int64_t{y} * (n - 1) + i, int64_t{x} * (n - 1) + j}] = block->at(i, j);
        }
      }
    }
  }
  return lattice;
}

TEST(TilerConditioning, FujiVoidsAreFilledWhereTheWorldGridSaysLand) {
  auto store = streaming::TileStore::open(bundledPyramid());
  ASSERT_TRUE(store) << store.error();
  const conditioning::DemGrid world = readRaw(kWorld);
  const conditioning::DemGrid raw = readRaw(kFuji);
  const Lattice lattice = readLattice(**store, kFujiLevel, 138.0, 35.0, 139.0, 36.0);
  ASSERT_GT(lattice.samples.size(), 1000000U);
  size_t checked = 0, low = 0;
  for (const auto& [index, sample] : lattice.samples) {
    const double lon = lattice.longitude(index.second), lat = lattice.latitude(index.first);
    if (lon < 138.0 || lon > 139.0 || lat < 35.0 || lat > 36.0) continue;
    // Vertices whose nearest SRTM sample is a void (no data): measured samples at or below 0 m
    // (a harbour behind its breakwater) are the data's own word.
    const auto row = std::lround((raw.firstRowLatitudeDegrees - lat) / raw.rowStepDegrees);
    const auto column =
        std::lround((lon - raw.firstColumnLongitudeDegrees) / raw.columnStepDegrees);
    if (raw.at(row, column) != terrain::kNoDataHeight) continue;
    if (conditioning::bilinearSurfaceMeters(world, lon, lat) <= 300.0) continue;
    ++checked;
    if (terrain::surfaceHeightMeters(sample) <= 0.0 && ++low <= 5) {
      ADD_FAILURE() << "at " << lon << "," << lat << ": " << sample << " (20′ grid "
                    << conditioning::bilinearSurfaceMeters(world, lon, lat) << " m)";
    }
  }
  EXPECT_GT(checked, 2000U);
  EXPECT_EQ(low, 0U) << "vertices at or below 0 m where the 20′ grid says > 300 m";
}

TEST(TilerConditioning, EachFilledHeightIsWithinItsVoidBorderRange) {
  // The tiler's own conditioning of the bundled inputs, checked void by void against the raw
  // Fuji samples: interpolated voids within their border's range; voids filled from the 20′ grid
  // within that range widened by how much the 20′ surface itself varies over the void.
  auto sources = openSources(bundledInputs(), {});
  ASSERT_TRUE(sources) << sources.error();
  ASSERT_TRUE(conditionSources(*sources));
  const conditioning::DemGrid raw = readRaw(kFuji);
  const conditioning::DemGrid world = readRaw(kWorld);
  const TilerSource* fuji = nullptr;
  for (const TilerSource& s : *sources) {
    if (s.argument == kFuji) fuji = &s;
  }
  ASSERT_NE(fuji, nullptr);
  std::vector<int16_t> filled(raw.samples.size());
  for (int64_t r = 0; r < raw.rows; ++r) {
    ASSERT_TRUE(fuji->raster->readRow(r, 0, raw.cols, filled.data() + raw.index(r, 0)));
  }
  std::vector<uint8_t> seen(raw.samples.size(), 0);
  size_t voids = 0, edgeVoids = 0, filledSamples = 0;
  for (size_t start = 0; start < raw.samples.size(); ++start) {
    if (raw.samples[start] != terrain::kNoDataHeight || seen[start] ||
        terrain::isWater(filled[start]))
      continue;
    // One void (4-connected), its border in the raw data, and the 20′ surface over it.
    std::vector<size_t> region{start};
    seen[start] = 1;
    double low = 1e9, high = -1e9, coarseLow = 1e9, coarseHigh = -1e9;
    for (size_t k = 0; k < region.size(); ++k) {
      const auto row = int64_t(region[k]) / raw.cols, column = int64_t(region[k]) % raw.cols;
      const double c = conditioning::bilinearSurfaceMeters(world, raw.longitudeDegrees(column),
                                                           raw.latitudeDegrees(row));
      coarseLow = std::min(coarseLow, c), coarseHigh = std::max(coarseHigh, c);
      for (auto [dr, dc] : {std::pair<int64_t, int64_t>{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
        const int64_t rr = row + dr, cc = column + dc;
        if (rr < 0 || rr >= raw.rows || cc < 0 || cc >= raw.cols) continue;
        const size_t i = raw.index(rr, cc);
        if (raw.samples[i] == terrain::kNoDataHeight) {
          if (!seen[i]) seen[i] = 1, region.push_back(i);
        } else {
          low = std::min(low, double(raw.samples[i])),
          high = std::max(high, double(raw.samples[i]));
        }
      }
    }
    // A void the tile's edge cuts is a hole like any other (SRTM's voids cross its tiles'
    // edges); only no data along a long stretch of the edge is outside the footprint, the 20′
    // grid showing through there bent to meet the data (FootprintBend).
    const auto onEdge = std::count_if(region.begin(), region.end(), [&](size_t i) {
      const auto row = int64_t(i) / raw.cols, column = int64_t(i) % raw.cols;
      return row == 0 || column == 0 || row == raw.rows - 1 || column == raw.cols - 1;
    });
    if (double(onEdge) >= conditioning::kOutsideBorderFraction * double(raw.rows)) continue;
    edgeVoids += onEdge > 0 ? 1 : 0;
    ++voids;
    const bool fromCoarser =
        int64_t(region.size()) > conditioning::FillOptions{}.smallVoidMaxSamples;
    const double slack = fromCoarser ? coarseHigh - coarseLow + 1.0 : 1.0;
    for (size_t i : region) {
      const auto row = int64_t(i) / raw.cols, column = int64_t(i) % raw.cols;
      const double lon = raw.longitudeDegrees(column), lat = raw.latitudeDegrees(row);
      ++filledSamples;
      EXPECT_FALSE(terrain::isWater(filled[i])) << lon << "," << lat;
      EXPECT_GE(filled[i], low - slack) << lon << "," << lat;
      EXPECT_LE(filled[i], high + slack) << lon << "," << lat;
    }
  }
  EXPECT_GT(voids, 20U);
  EXPECT_GT(edgeVoids, 0U) << "the bundled tile has voids its edges cut";
  EXPECT_GT(filledSamples, 1500U);
}

TEST(TilerConditioning, NoWallWhereTheFujiTileMeetsTheWorldGrid) {
  // Steps between neighbouring level-14 vertices: across the Fuji tile's edges no larger than
  // the 99.9th percentile of steps inside it.
  auto store = streaming::TileStore::open(bundledPyramid());
  ASSERT_TRUE(store) << store.error();
  const double west = 138.0 - 1.0 / 2400, east = 139.0 + 1.0 / 2400;  // the cells' extent
  const double south = 35.0 - 1.0 / 2400, north = 36.0 + 1.0 / 2400;
  const Lattice lattice =
      readLattice(**store, kFujiLevel, west - 0.005, south - 0.005, east + 0.005, north + 0.005);
  auto inside = [&](double lon, double lat) {
    return lon >= west && lon <= east && lat >= south && lat <= north;
  };
  std::vector<double> insideSteps;
  double worstAcross = 0, worstCoast = 0;
  for (const auto& [index, sample] : lattice.samples) {
    for (auto [dr, dc] : {std::pair<int64_t, int64_t>{0, 1}, {1, 0}}) {
      const auto other = lattice.at(index.first + dr, index.second + dc);
      if (!other) continue;
      const bool a = inside(lattice.longitude(index.second), lattice.latitude(index.first));
      const bool b =
          inside(lattice.longitude(index.second + dc), lattice.latitude(index.first + dr));
      const double step =
          std::abs(terrain::surfaceHeightMeters(sample) - terrain::surfaceHeightMeters(*other));
      if (a && b) insideSteps.push_back(step);
      // Where the SRTM tile says sea at its edge and the 20′ grid beyond says land, the two
      // disagree about the coast itself: the grid's land bends down to the water (FootprintBend).
      if (a != b && (terrain::isWater(sample) || terrain::isWater(*other))) {
        worstCoast = std::max(worstCoast, step);
      }
      if (a != b) worstAcross = std::max(worstAcross, step);
    }
  }
  ASSERT_GT(insideSteps.size(), 1000000U);
  const size_t k = insideSteps.size() * 999 / 1000;
  std::nth_element(insideSteps.begin(), insideSteps.begin() + long(k), insideSteps.end());
  const double p999 = insideSteps[k];
  RecordProperty("worstStepAcrossMeters", std::to_string(worstAcross));
  RecordProperty("p999StepInsideMeters", std::to_string(p999));
  std::printf(
      "Fuji edge: worst step across %.1f m (%.1f m where one side is water), p99.9 "
      "inside %.1f m\n",
      worstAcross, worstCoast, p999);
  EXPECT_LE(worstAcross, p999);
}

TEST(TilerConditioning, SrtmZeroMetreSeaIsWater) {
  // Suruga Bay is written as exactly 0 m in the SRTM tile: the pyramid draws it as water.
  const conditioning::DemGrid raw = readRaw(kFuji);
  auto store = streaming::TileStore::open(bundledPyramid());
  ASSERT_TRUE(store) << store.error();
  const Lattice lattice = readLattice(**store, kFujiLevel, 138.0, 35.0, 139.0, 36.0);
  size_t zero = 0, water = 0;
  for (const auto& [index, sample] : lattice.samples) {
    const double lon = lattice.longitude(index.second), lat = lattice.latitude(index.first);
    if (lon < 138.01 || lon > 138.99 || lat < 35.01 || lat > 35.99) continue;
    const auto row = std::lround((raw.firstRowLatitudeDegrees - lat) / raw.rowStepDegrees);
    const auto column =
        std::lround((lon - raw.firstColumnLongitudeDegrees) / raw.columnStepDegrees);
    if (raw.at(row, column) != 0) continue;
    ++zero;
    if (terrain::isWater(sample)) ++water;
  }
  EXPECT_GT(zero, 40000U);
  EXPECT_GE(double(water), 0.98 * double(zero)) << water << " of " << zero;
}

TEST(TilerConditioning, TheKattegatAtZeroMetresIsWater) {
  // N57E011 is mostly sea written as exactly 0 m; tiled with the 20′ grid, that sea is water.
  const std::string kattegat =
      std::string(GLOBE_SOURCE_DIR) + "/tests/data/dem/gtopo30/N57E011.DEM";
  const auto dir = globe::testing::freshTempDir("kattegat");
  TilerOptions options;
  options.inputs = {kWorld, kattegat};
  options.outputDir = dir / "pyramid";
  ASSERT_TRUE(runTiler(options));
  auto store = streaming::TileStore::open(options.outputDir);
  ASSERT_TRUE(store) << store.error();
  const conditioning::DemGrid raw = readRaw(kattegat);
  const Lattice lattice = readLattice(**store, kFujiLevel, 11.0, 57.0, 12.0, 58.0);
  size_t zero = 0, water = 0, land = 0, landAsWater = 0;
  for (const auto& [index, sample] : lattice.samples) {
    const double lon = lattice.longitude(index.second), lat = lattice.latitude(index.first);
    if (lon < 11.01 || lon > 11.99 || lat < 57.01 || lat > 57.99) continue;
    const auto row = std::lround((raw.firstRowLatitudeDegrees - lat) / raw.rowStepDegrees);
    const auto column =
        std::lround((lon - raw.firstColumnLongitudeDegrees) / raw.columnStepDegrees);
    const int16_t source = raw.at(row, column);
    if (source == 0) {
      ++zero;
      water += terrain::isWater(sample) ? 1 : 0;
    } else if (source > 5) {
      ++land;
      landAsWater += terrain::isWater(sample) ? 1 : 0;
    }
  }
  std::printf("Kattegat: %zu of %zu 0 m vertices water; %zu of %zu land vertices water\n", water,
              zero, landAsWater, land);
  EXPECT_GT(zero, 500000U);
  EXPECT_GE(double(water), 0.95 * double(zero));
  EXPECT_LE(double(landAsWater), 0.001 * double(land));
}

TEST(TilerConditioning, SpilledAndParallelConditioningReadsTheSameAsInMemory) {
  // A zero memory budget spills every source no finer one needs (Fuji, W002N52) to unlinked
  // files; two threads condition equally fine sources together. The samples read back alike.
  auto inMemory = openSources(bundledInputs(), {});
  auto spilled = openSources(bundledInputs(), {});
  ASSERT_TRUE(inMemory && spilled);
  ASSERT_TRUE(conditionSources(*inMemory));
  ConditioningOptions options;
  options.threads = 2;
  options.spillDirectory = globe::testing::freshTempDir("spill");
  options.memoryBudgetBytes = 0;
  auto report = conditionSources(*spilled, options);
  ASSERT_TRUE(report) << report.error();
  EXPECT_TRUE(std::filesystem::is_empty(options.spillDirectory)) << "spill files are unlinked";
  for (size_t i = 0; i < inMemory->size(); ++i) {
    const geo::SampleGrid& g = (*inMemory)[i].grid;
    std::vector<int16_t> a(static_cast<size_t>(g.cols)), b(a.size());
    for (int64_t r = 0; r < g.rows; ++r) {
      ASSERT_TRUE((*inMemory)[i].raster->readRow(r, 0, g.cols, a.data()));
      ASSERT_TRUE((*spilled)[i].raster->readRow(r, 0, g.cols, b.data()));
      ASSERT_EQ(a, b) << (*inMemory)[i].argument << " row " << r;
    }
    // Wrapped reads across the antimeridian go through the same path.
    if (g.wrapsLongitude) {
      ASSERT_TRUE((*inMemory)[i].raster->readRow(3, g.cols - 2, 5, a.data()));
      ASSERT_TRUE((*spilled)[i].raster->readRow(3, g.cols - 2, 5, b.data()));
      EXPECT_TRUE(std::equal(a.begin(), a.begin() + 5, b.begin()));
    }
  }
}

TEST(TilerConditioning, AnInputTooLargeToConditionIsAClearError) {
  // A VRT declaring 40000×30000 samples (0 m behind it, nothing stored): refused before the
  // conditioning reads it (the valid-sample check reads two rows).
  const auto dir = globe::testing::freshTempDir("huge");
  const auto vrt = dir / "huge.vrt";
  std::ofstream(vrt) << R"(<VRTDataset rasterXSize="40000" rasterYSize="30000">
  <SRS>EPSG:4326</SRS>
  <GeoTransform>0, 0.00025, 0, 10, 0, -0.00025</GeoTransform>
  <VRTRasterBand dataType="Int16" band="1"></VRTRasterBand>
</VRTDataset>)";
  TilerOptions options;
  options.inputs = {vrt.string()};
  options.outputDir = dir / "pyramid";
  auto report = runTiler(options);
  ASSERT_FALSE(report);
  EXPECT_NE(report.error().find("huge.vrt"), std::string::npos) << report.error();
  EXPECT_NE(report.error().find("split it into tiles"), std::string::npos) << report.error();
}

// A GTOPO30-format raster of 40×40 no-data samples at the given step, written to dir/STEM.
std::string allNoData(const std::filesystem::path& dir, const std::string& stem,
                      double stepDegrees) {
  rasters::Gtopo30Raster raster;
  raster.header.rows = raster.header.cols = 40;
  raster.header.ulxMapDegrees = 10.0 + stepDegrees / 2;
  raster.header.ulyMapDegrees = 46.0 - stepDegrees / 2;
  raster.header.xDimDegrees = raster.header.yDimDegrees = stepDegrees;
  raster.header.bandRowBytes = raster.header.totalRowBytes = 80;
  raster.heights.assign(1600, terrain::kNoDataHeight);
  EXPECT_TRUE(rasters::writeGtopo30(dir / stem, raster));
  return (dir / (stem + ".DEM")).string();
}

TEST(TilerConditioning, ASourceThatIsAllNoDataIsRefusedUnlessItsNoDataIsSea) {
  const auto dir = globe::testing::freshTempDir("all-no-data");
  TilerOptions options;
  options.outputDir = dir / "pyramid";
  // Missing data everywhere: nothing to tile, and the error names the file.
  options.inputs = {kWorld, allNoData(dir, "EMPTY", 0.025)};
  auto refused = runTiler(options);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("EMPTY.DEM: fewer than 2x2 valid samples (every sample is no "
                                 "data)"),
            std::string::npos)
      << refused.error();
  // GTOPO30's own 30″ grid: its -9999 is the ocean mask, an all-sea tile.
  options.inputs = {kWorld, allNoData(dir, "OCEAN", 1.0 / 120.0)};
  options.outputDir = dir / "ocean";
  auto report = runTiler(options);
  ASSERT_TRUE(report) << report.error();
  ASSERT_EQ(report->warnings.size(), 1U);
  EXPECT_NE(report->warnings[0].find("OCEAN.DEM"), std::string::npos);
  EXPECT_NE(report->warnings[0].find("tiled as sea"), std::string::npos);
}

}  // namespace
}  // namespace globe::tiling
