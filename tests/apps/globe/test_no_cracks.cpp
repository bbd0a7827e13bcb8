// No background shows through the ground anywhere: low, grazing views across every edge of the
// bundled elevation sources (Zion's SRTM under its Landsat layer, which refines the terrain past
// its data; Fuji's 3″ and the GTOPO30 tile by the Wash under the Blue Marble), through the real
// program with --no-sky (space black). Every black pixel below a column's first ground pixel is
// a crack. Before seams were made watertight (terrain/tile_transform.hpp), 35 such pixels showed
// in 15 of 128 views along Zion's edges, dotted along tile seams on slopes.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "formats/image_io.hpp"
#include "tests/apps/globe/run_globe.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;
using test::runGlobe;

struct Source {
  std::string name;
  double west, south, east, north;  // degrees
};

// Background pixels (exactly black) below the first ground pixel of their column.
int cracksBelowSkyline(const formats::ImageRgba& image) {
  int cracks = 0;
  for (int x = 0; x < image.widthPixels; ++x) {
    bool ground = false;
    for (int y = 0; y < image.heightPixels; ++y) {
      const size_t i = 4 * (static_cast<size_t>(y) * image.widthPixels + static_cast<size_t>(x));
      const bool black = image.pixels[i] == 0 && image.pixels[i + 1] == 0 && image.pixels[i + 2] == 0;
      if (!black) ground = true;
      if (black && ground) ++cracks;
    }
  }
  return cracks;
}

// Cameras 150 m above the ground on each edge's midpoint and two corners, looking along the edge
// and across it, 4° down; every view must show ground and no crack.
void expectNoCracks(const fs::path& pyramid, const std::string& layer, const Source& source) {
  const double midLon = 0.5 * (source.west + source.east);
  const double midLat = 0.5 * (source.south + source.north);
  struct Place {
    double lon, lat;
    std::vector<int> headings;
  };
  const std::vector<Place> places = {
      {source.west, midLat, {0, 90, 180}}, {source.east, midLat, {0, 270}},
      {midLon, source.north, {90, 180, 270}}, {midLon, source.south, {0, 90}},
      {source.west, source.north, {135}}, {source.east, source.south, {315}}};
  const fs::path dir = globe::testing::freshTempDir("no-cracks");
  int views = 0;
  for (const Place& place : places) {
    for (const int heading : place.headings) {
      std::ostringstream camera;
      camera.precision(10);
      camera << place.lon << "," << place.lat << ",150," << heading << ",-4,0";
      const fs::path out = dir / (source.name + std::to_string(++views) + ".png");
      const auto run = runGlobe("snapshot " + pyramid.string() + " --layer " + layer +
                                " --above-terrain --no-sky --camera " + camera.str() + " -o " +
                                out.string());
      ASSERT_EQ(run.exitCode, 0) << run.output;
      auto image = formats::loadImageRgba(out);
      ASSERT_TRUE(image) << image.error();
      EXPECT_EQ(cracksBelowSkyline(*image), 0) << source.name << " " << camera.str();
    }
  }
  EXPECT_EQ(views, 12);
}

TEST(NoCracks, AcrossZionsEdgesUnderItsLandsatLayer) {
  expectNoCracks(globe::testing::zionPyramid(), globe::testing::zionLayer().string(),
                 {"zion", -113.2396, 37.1321, -112.8521, 37.5129});
}

TEST(NoCracks, AcrossFujiAndTheWashUnderTheBlueMarble) {
  const std::string layer = globe::testing::blueMarbleLayer().string();
  expectNoCracks(globe::testing::bundledPyramid(), layer,
                 {"fuji", 137.9996, 34.9996, 139.0004, 36.0004});
  expectNoCracks(globe::testing::bundledPyramid(), layer, {"wash", -2.0, 52.0, 0.0, 54.0});
}

}  // namespace
}  // namespace globe::app
