// `globe info`: the real program on the bundled pyramid, text and JSON, and its bad-input errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/apps/globe/run_globe.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace {

using globe::app::test::ProcessResult;
using globe::app::test::runGlobe;

TEST(GlobeInfo, JsonListsLevelsTilesBoundsAndHeights) {
  const auto pyramid = globe::testing::bundledPyramid();
  const ProcessResult run = runGlobe("info --json " + pyramid.string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto j = nlohmann::json::parse(run.output);
  EXPECT_EQ(j["blockSize"], 17);
  EXPECT_EQ(j["minLevel"], 0);
  EXPECT_EQ(j["maxLevel"], 14);
  ASSERT_EQ(j["levels"].size(), 15u);
  EXPECT_EQ(j["levels"][0]["tiles"], 2);
  uint64_t sum = 0;
  for (const auto& level : j["levels"]) sum += level["tiles"].get<uint64_t>();
  EXPECT_EQ(j["tiles"].get<uint64_t>(), sum);
  EXPECT_LT(j["heightRangeMeters"][0].get<int>(), -5000);  // ETOPO20 sea floor
  EXPECT_GT(j["heightRangeMeters"][1].get<int>(), 3700);   // Fuji
  // The finest level sits over Mount Fuji.
  EXPECT_NEAR(j["finestBoundsDegrees"]["west"].get<double>(), 138.0, 0.05);
  EXPECT_NEAR(j["finestBoundsDegrees"]["north"].get<double>(), 36.0, 0.05);
  EXPECT_EQ(j["sources"].size(), 3u);
  // The Fuji SRTM tile (finest first): its voids filled, its 0 m sea written as water.
  const auto& fuji = j["sources"][0]["conditioning"];
  EXPECT_EQ(fuji["voidSamples"].get<uint64_t>(),
            fuji["voidsFilledByInterpolation"].get<uint64_t>() +
                fuji["voidsFilledFromCoarserSource"].get<uint64_t>());
  EXPECT_GT(fuji["voidSamples"].get<uint64_t>(), 2000u);
  EXPECT_GT(fuji["seaSamples"].get<uint64_t>(), 50000u);
}

TEST(GlobeInfo, TextHasOneLinePerLevel) {
  const ProcessResult run = runGlobe("info " + globe::testing::bundledPyramid().string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("levels      0..14"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("E138N35_FUJI.DEM"), std::string::npos);
  EXPECT_NE(run.output.find("from a coarser source, 0 left"), std::string::npos) << run.output;
}

TEST(GlobeInfo, NotAPyramidIsAClearError) {
  const auto dir = globe::testing::freshTempDir("not-a-pyramid");
  const ProcessResult run = runGlobe("info " + dir.string());
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.output.find("manifest.json"), std::string::npos) << run.output;
  const ProcessResult badGlobe = runGlobe("info --globe mars " + dir.string());
  EXPECT_EQ(badGlobe.exitCode, 2) << badGlobe.output;
}

// An imagery layer directory: its levels, tiles and sources, as text and as layer.json's JSON.
TEST(GlobeInfo, DescribesAnImageryLayer) {
  const auto layer = globe::testing::zionLayer();
  const ProcessResult text = runGlobe("info " + layer.string());
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_NE(text.output.find("layer "), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("256x256 pixels"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("levels      0..12"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("zion-landsat8-rgb.tif"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("EPSG:32612"), std::string::npos) << text.output;
  const ProcessResult json = runGlobe("info --json " + layer.string());
  ASSERT_EQ(json.exitCode, 0) << json.output;
  const auto j = nlohmann::json::parse(json.output);
  EXPECT_EQ(j["kind"], "imagery");
  EXPECT_EQ(j["levels"].size(), 13u);
}

}  // namespace
