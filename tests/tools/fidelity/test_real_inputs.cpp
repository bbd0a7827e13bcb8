// Real inputs drawn as they are (issue "the finest source is the truth"): awkward cases made from
// the repository's DEMs, tiled by the real tiler, and measured independently of it
// (tools/fidelity): a source is never altered inside its footprint, there is no wall at its
// edge, and no data is never drawn as sea where nothing says sea.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "streaming/tile_store.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "tests/tools/fidelity/real_input_cases.hpp"
#include "tools/fidelity/input_fidelity.hpp"

namespace globe::fidelity {
namespace {

namespace fs = std::filesystem;
const std::string kData = std::string(GLOBE_SOURCE_DIR) + "/tests/data/dem/";
const std::string kWorld = kData + "gtopo30/ETOPO20.DEM";
const std::string kFujiTiff = kData + "original/mt_fuji_90m.tif";
// Block resampling: a vertex between samples is their bilinear value, rounded to the metre.
constexpr double kResamplingMeters = 0.5 + 1e-6;

// Tiles the inputs and measures how the pyramid draws each of them that has an edge.
std::vector<SourceFidelity> tileAndMeasure(const std::string& name,
                                           const std::vector<std::string>& inputs) {
  const fs::path pyramid = globe::testing::tilePyramid(name + "-pyramid", inputs);
  auto store = streaming::TileStore::open(pyramid.string());
  EXPECT_TRUE(store) << store.error();
  if (!store) return {};
  auto inputsMeasured = measureInputs(**store, inputs);
  EXPECT_TRUE(inputsMeasured) << inputsMeasured.error();
  if (!inputsMeasured) return {};
  std::vector<SourceFidelity> measured;
  for (const auto& [argument, f] : *inputsMeasured) {
    std::printf(
        "%s %s: |drawn - source| inside p95 %.1f max %.1f m (%llu), edge band p95 %.1f max "
        "%.1f m (%llu); steps across the edge worst %.1f m (source p99.9 %.1f m), %llu of %llu "
        "over 1.5x the local step; %llu of %llu vertices over no data drawn as sea over land\n",
        name.c_str(), fs::path(argument).filename().c_str(), f.inside.p95Meters, f.inside.maxMeters,
        static_cast<unsigned long long>(f.inside.count), f.edgeBand.p95Meters, f.edgeBand.maxMeters,
        static_cast<unsigned long long>(f.edgeBand.count), f.worstStepAcrossMeters,
        f.sourceP999StepMeters, static_cast<unsigned long long>(f.stepsOverLocalBound),
        static_cast<unsigned long long>(f.edgePairs),
        static_cast<unsigned long long>(f.noDataDrawnAsSeaOverLand),
        static_cast<unsigned long long>(f.noDataVertices));
    measured.push_back(f);
  }
  return measured;
}

// The source drawn as it is inside its footprint, alike inside and along its edges.
void expectUnaltered(const SourceFidelity& f) {
  EXPECT_GT(f.inside.count, 10000U);
  EXPECT_GT(f.edgeBand.count, 10000U);
  EXPECT_LE(f.inside.maxMeters, kResamplingMeters);
  EXPECT_LE(f.edgeBand.maxMeters, kResamplingMeters);
}

void expectNoWallAndNoFalseSea(const SourceFidelity& f) {
  EXPECT_GT(f.edgePairs, 1000U);
  EXPECT_EQ(f.stepsOverLocalBound, 0U) << "worst step " << f.worstStepAcrossMeters << " m, "
                                       << f.worstLocalStepRatio << "x the local bound";
  EXPECT_EQ(f.noDataDrawnAsSeaOverLand, 0U) << "of " << f.noDataVertices;
}

TEST(RealInputs, ASummitAtTheEdgeIsDrawnAtItsMeasuredHeight) {
  // Mount Fuji's summit (138.7275°E, 35.3606°N) 0.01° inside the crop's north edge.
  const fs::path dir = globe::testing::freshTempDir("summit-edge");
  testing::cropRaster(kFujiTiff, dir / "fuji-crop.tif", 138.55, 35.10, 138.95, 35.37);
  const auto measured = tileAndMeasure("summit-edge", {kWorld, (dir / "fuji-crop.tif").string()});
  ASSERT_EQ(measured.size(), 1U);
  expectUnaltered(measured[0]);
  expectNoWallAndNoFalseSea(measured[0]);
}

TEST(RealInputs, ABlankedHalfOfACoastalTileShowsTheCoarserSeaAndLand) {
  // The Fuji tile's south half (Suruga Bay, the Izu peninsula) blanked: the 20′ grid has both
  // sea and land along that coast.
  const fs::path dir = globe::testing::freshTempDir("blanked-half");
  testing::blankRaster(kFujiTiff, dir / "fuji-north.tif",
                       [](double, double latitude) { return latitude < 35.5; });
  const auto measured = tileAndMeasure("blanked-half", {kWorld, (dir / "fuji-north.tif").string()});
  ASSERT_EQ(measured.size(), 1U);
  expectUnaltered(measured[0]);
  expectNoWallAndNoFalseSea(measured[0]);
  EXPECT_GT(measured[0].noDataVertices, 500000U);
}

TEST(RealInputs, TwoAdjacentSrtmTilesJoinUntouched) {
  const auto measured = tileAndMeasure(
      "adjacent", {kWorld, kData + "gtopo30/N50E008.DEM", kData + "gtopo30/N50E009.DEM"});
  ASSERT_EQ(measured.size(), 2U);
  for (const SourceFidelity& f : measured) {
    expectUnaltered(f);
    expectNoWallAndNoFalseSea(f);
  }
}

TEST(RealInputs, ADemWarpedToUtmHasNoMoatsAndNoWalls) {
  // Warped to UTM 54N and back to lat/long by the tiler: no-data wedges along every side.
  const fs::path dir = globe::testing::freshTempDir("utm");
  testing::warpRaster(kFujiTiff, dir / "fuji-utm.tif", "EPSG:32654", 90.0);
  const auto measured = tileAndMeasure("utm", {kWorld, (dir / "fuji-utm.tif").string()});
  ASSERT_EQ(measured.size(), 1U);
  expectUnaltered(measured[0]);
  expectNoWallAndNoFalseSea(measured[0]);
  EXPECT_GT(measured[0].noDataVertices, 10000U);  // the wedges
}

TEST(RealInputs, ANoDataCollarShowsTheCoarserGridBentToTheData) {
  // A collar of no data three samples wide round the tile (as GeoTIFF exports often have): one
  // thin ring of outside samples, bent on its own samples rather than over the whole tile.
  const fs::path dir = globe::testing::freshTempDir("collar");
  testing::blankRaster(kFujiTiff, dir / "fuji-collar.tif", [](double lon, double lat) {
    return lon < 138.0025 || lon > 138.9975 || lat < 35.0025 || lat > 35.9975;
  });
  const auto measured = tileAndMeasure("collar", {kWorld, (dir / "fuji-collar.tif").string()});
  ASSERT_EQ(measured.size(), 1U);
  expectUnaltered(measured[0]);
  expectNoWallAndNoFalseSea(measured[0]);
  EXPECT_GT(measured[0].noDataVertices, 10000U);
}

TEST(RealInputs, WithoutACoarserSourceNoDataIsFilledNeverSea) {
  // The Fuji tile alone: its voids, some reaching the tile's edge, are filled, not sea shafts.
  const auto measured = tileAndMeasure("alone", {kFujiTiff});
  ASSERT_EQ(measured.size(), 1U);
  EXPECT_GT(measured[0].noDataVertices, 1000U);
  EXPECT_EQ(measured[0].noDataDrawnAsSeaOverLand, 0U);
  EXPECT_LE(measured[0].inside.maxMeters, kResamplingMeters);
}

}  // namespace
}  // namespace globe::fidelity
