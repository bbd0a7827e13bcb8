// A water mask through the real programs: globe-tiler water-mask on a polygon made here, then
// globe snapshot over the 20' world grid alone. An island the grid cannot see (open Pacific) is
// drawn as land with the mask and as sea without it; outside the polygons' extent the grid's own
// sea stays.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "formats/image_io.hpp"
#include "tests/apps/globe/run_globe.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;
using test::runGlobe;

struct Pixel {
  int r, g, b;
};

Pixel pixelAt(const formats::ImageRgba& image, int x, int y) {
  const size_t i = 4 * (static_cast<size_t>(y) * static_cast<size_t>(image.widthPixels) +
                        static_cast<size_t>(x));
  return {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]};
}

TEST(GlobeWaterMask, AnIslandTheGridCannotSeeIsDrawnFromItsPolygon) {
  const fs::path dir = globe::testing::freshTempDir("water-mask-snapshot");
  const fs::path pyramid = globe::testing::tilePyramid(
      "water-mask-etopo", {std::string(GLOBE_SOURCE_DIR) + "/data/dem/ETOPO20.DEM"});
  // A 2-degree island in the open South Pacific, where the grid is 4 km deep.
  std::ofstream(dir / "island.geojson")
      << R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},)"
         R"("geometry":{"type":"Polygon","coordinates":[[[-134,-29],[-132,-29],[-132,-27],)"
         R"([-134,-27],[-134,-29]]]}}]})";
  const std::string tiler = std::string(GLOBE_TILER_EXE) + " water-mask -q -o " +
                            (dir / "mask").string() + " " + (dir / "island.geojson").string();
  ASSERT_EQ(std::system(tiler.c_str()), 0) << tiler;

  // Straight down from 1,000 km: the island spans ~40 of 101 pixels.
  const std::string camera = " --camera -133,-28,1000000 --size 101x101 ";
  const auto without =
      runGlobe("snapshot " + pyramid.string() + camera + "-o " + (dir / "without.png").string());
  ASSERT_EQ(without.exitCode, 0) << without.output;
  const auto with = runGlobe("snapshot " + pyramid.string() + camera + "--layer " +
                             (dir / "mask").string() + " -o " + (dir / "with.png").string());
  ASSERT_EQ(with.exitCode, 0) << with.output;
  auto plain = formats::loadImageRgba(dir / "without.png");
  auto masked = formats::loadImageRgba(dir / "with.png");
  ASSERT_TRUE(plain) << plain.error();
  ASSERT_TRUE(masked) << masked.error();

  auto isSea = [](Pixel p) { return p.b > p.g + 20 && p.b > p.r + 20; };
  auto isLand = [](Pixel p) { return p.g > p.b + 20; };
  const Pixel centreWithout = pixelAt(*plain, 50, 50), centreWith = pixelAt(*masked, 50, 50);
  EXPECT_TRUE(isSea(centreWithout))
      << centreWithout.r << "," << centreWithout.g << "," << centreWithout.b;
  EXPECT_TRUE(isLand(centreWith)) << centreWith.r << "," << centreWith.g << "," << centreWith.b;
  // A corner lies outside the island and its extent: sea in both.
  EXPECT_TRUE(isSea(pixelAt(*masked, 3, 3)));
  // The island's edge is straight and where the polygon is: count land pixels along the middle
  // row; a 2-degree island at 1,000 km fills about 2/5 of a 101-pixel row (45 deg vertical field
  // of view would make it ~45; allow the projection's spread).
  int land = 0;
  for (int x = 0; x < 101; ++x) land += isLand(pixelAt(*masked, x, 50)) ? 1 : 0;
  EXPECT_GT(land, 15);
  EXPECT_LT(land, 90);
}

}  // namespace
}  // namespace globe::app
