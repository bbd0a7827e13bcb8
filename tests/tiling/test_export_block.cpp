// globe-tiler export writes strict GTOPO30: every water sample (band-coded over a known floor or
// -9999) as -9999, land as stored, below sea level and next to the codes included.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "rasters/gtopo30.hpp"
#include "tests/support/sea_test_pyramid.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "tiling/export_block.hpp"

namespace globe::tiling {
namespace {

TEST(ExportBlock, WaterIsWrittenAsNoDataAndLandAsIs) {
  const auto dir = globe::testing::freshTempDir("export-sea");
  ASSERT_TRUE(globe::testing::writeSeaTestPyramid(dir / "pyramid"));
  const auto stem = dir / "mixed";
  auto exported = exportBlock(dir / "pyramid", globe::testing::kMixedTile, stem);
  ASSERT_TRUE(exported) << exported.error();
  auto raster = rasters::readGtopo30(stem);
  ASSERT_TRUE(raster) << raster.error();
  const terrain::HeightBlock stored = globe::testing::seaTestBlock(globe::testing::kMixedTile);
  ASSERT_EQ(raster->heights.size(), stored.heights.size());
  size_t water = 0, banded = 0, belowSeaLevel = 0;
  for (size_t k = 0; k < stored.heights.size(); ++k) {
    const int16_t sample = stored.heights[k];
    if (terrain::isWater(sample)) {
      EXPECT_EQ(raster->heights[k], terrain::kNoDataHeight) << "sample " << sample;
      ++water;
      banded += sample != terrain::kNoDataHeight;
    } else {
      EXPECT_EQ(raster->heights[k], sample);
      belowSeaLevel += sample < 0;
    }
  }
  EXPECT_GT(banded, 0u);
  EXPECT_GT(water, banded);
  EXPECT_GT(belowSeaLevel, 0u);  // -400, -9998, -10000 stay land
  EXPECT_EQ(raster->header.noData, terrain::kNoDataHeight);
  // The .STX's minimum is the lowest land (-10000 m), not a band code.
  std::stringstream stx;
  stx << std::ifstream(stem.string() + ".STX").rdbuf();
  EXPECT_EQ(stx.str().rfind("1 -10000 250 ", 0), 0u) << stx.str();
}

}  // namespace
}  // namespace globe::tiling
