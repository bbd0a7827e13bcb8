// Screenshot regression: views of the bundled real data (some with imagery layers or the water
// mask) rendered by the real `globe snapshot` program through OSMesa, compared with the goldens in
// tests/render/golden. Tolerance: a pixel differs when a channel is off by more than 24 (of 255);
// at most 0.5% of the pixels may differ. On failure the actual image and a diff image are written
// next to the test output. Regenerate the goldens (then look at them!) with:
//   GLOBE_UPDATE_GOLDENS=1 ctest --test-dir build -R globe_golden_tests
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "formats/image_io.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/golden_compare.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe {
namespace {

namespace fs = std::filesystem;
constexpr int kChannelTolerance = 24;
constexpr double kMaxDifferingFraction = 0.005;

struct GoldenView {
  const char* name;
  const char* arguments;     // after `globe snapshot PYRAMID`; @bm and @zion name imagery layers
  bool zionPyramid = false;  // ETOPO20 + Zion's SRTM instead of the bundled pyramid
};

const GoldenView kViews[] = {
    {"globe_from_space", "--camera 138,30,20000000"},
    {"fuji_oblique", "--camera 138.60,35.20,6000,30,-15,0"},
    {"ground_2m_horizon", "--camera 138.70,35.30,2,0,0,0 --above-terrain"},
    {"north_pole", "--camera 0,90,3000000"},
    {"south_pole", "--camera 0,-90,3000000"},
    {"antimeridian_bering", "--camera 180,58,1800000,0,-45,0"},
    {"coast_suruga_bay", "--camera 138.62,34.85,9000,10,-25,0"},
    {"mid_refinement", "--camera 138.60,35.20,6000,30,-15,0 --max-load-level 9"},
    {"globe_blue_marble", "--camera 138,30,20000000 --layer @bm"},
    {"fuji_oblique_blue_marble_lit", "--camera 138.60,35.20,6000,30,-15,0 --layer @bm --lighting"},
    {"zion_oblique_layers", "--camera -112.93,37.16,4500,330,-20,0 --layer @bm --layer @zion",
     true},
    {"zion_nadir_half_opacity", "--camera -112.98,37.27,9000 --layer @zion,0.5", true},
    // The sky (render/sky_model.hpp) from the ground, from 10 km and from space.
    {"sky_ground", "--camera 138.70,35.30,2,300,5,0 --above-terrain"},
    {"sky_10km", "--camera 138.60,35.20,10000,30,-5,0"},
    {"sky_space", "--camera 138,30,3000000,0,-40,0"},
    {"sky_off_10km", "--camera 138.60,35.20,10000,30,-5,0 --no-sky"},
    // True coasts from the bundled water mask: the Wash over ETOPO20 (east of 0°) and the GTOPO30
    // crop (west of it), Suruga Bay as coast_suruga_bay, and north-western Europe from 2,500 km.
    {"wash_water_mask", "--camera 0.3,52.9,60000 --layer @coast"},
    {"coast_suruga_bay_water_mask", "--camera 138.62,34.85,9000,10,-25,0 --layer @coast"},
    {"europe_water_mask", "--camera 2,54,2500000 --layer @coast"},
    // Overlays: draped lines and polygons, labels decluttered and hidden
    // by terrain, 3D walls, a ground overlay from a KMZ, real files from the ecosystem.
    {"fuji_overlays",
     "--camera 138.80,35.25,9000,315,-25,0 --overlay @repo/data/overlays/fuji-demo.kml"},
    {"globe_countries_places",
     "--camera 10,30,12000000 --layer @bm"
     " --overlay @data/interop/overlays/ne_110m_admin_0_countries.geojson"
     " --overlay @data/interop/overlays/ne_110m_rivers_lake_centerlines.geojson"
     " --overlay @data/interop/overlays/ne_110m_populated_places_simple.geojson"},
    {"etna_ground_overlay",
     "--camera 14.98,37.20,70000,0,-50,0 --overlay-hidden"
     " --overlay @data/interop/overlays/etna.kmz"},
    {"alaska_gnis_labels",
     "--camera -150,62,3500000 --overlay @data/interop/overlays/gnis-ak-first-101.kml"},
    {"manchester_metrolink",
     "--camera -2.24,53.36,14000,0,-55,0"
     " --overlay @data/interop/overlays/tfgm-Metrolink_Lines_Functional.kml"
     " --overlay @data/interop/overlays/tfgm-Metrolink_Stops_Functional.kml"},
};

// The view's arguments with the layer placeholders replaced by the layers (tiled once) and @data/
// by the checkout's tests/data/, @repo/ by the checkout.
std::string expandLayers(std::string arguments) {
  const std::pair<const char*, const fs::path& (*)()> layers[] = {
      {"@bm", globe::testing::blueMarbleLayer},
      {"@zion", globe::testing::zionLayer},
      {"@coast", globe::testing::coastMask}};
  const std::pair<std::string, std::string> directories[] = {
      {"@data/", std::string(GLOBE_SOURCE_DIR) + "/tests/data/"},
      {"@repo/", std::string(GLOBE_SOURCE_DIR) + "/"}};
  for (const auto& [token, directory] : directories) {
    for (size_t at = arguments.find(token); at != std::string::npos; at = arguments.find(token)) {
      arguments.replace(at, token.size(), directory);
    }
  }
  for (const auto& [token, layer] : layers) {
    for (size_t at = arguments.find(token); at != std::string::npos; at = arguments.find(token)) {
      arguments.replace(at, std::string(token).size(), layer().string());
    }
  }
  return arguments;
}

// Names the parameter in test output instead of dumping its bytes.
void PrintTo(const GoldenView& view, std::ostream* out) { *out << view.name; }

class GoldenImages : public ::testing::TestWithParam<GoldenView> {};

TEST_P(GoldenImages, MatchesTheCommittedGolden) {
  const GoldenView& view = GetParam();
  const fs::path outDir = fs::path(globe::build_paths::binaryDir()) / "tests/render/golden-output";
  fs::create_directories(outDir);
  const fs::path actualPath = outDir / (std::string(view.name) + ".actual.png");
  const fs::path& pyramid =
      view.zionPyramid ? globe::testing::zionPyramid() : globe::testing::bundledPyramid();
  const std::string command = std::string(GLOBE_EXE) + " snapshot " + pyramid.string() + " " +
                              expandLayers(view.arguments) + " --size 480x270 -o " +
                              actualPath.string() + " > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  auto actual = formats::loadImageRgba(actualPath);
  ASSERT_TRUE(actual) << actual.error();

  const fs::path goldenPath =
      fs::path(GLOBE_SOURCE_DIR) / "tests/render/golden" / (std::string(view.name) + ".png");
  if (std::getenv("GLOBE_UPDATE_GOLDENS") != nullptr) {
    fs::copy_file(actualPath, goldenPath, fs::copy_options::overwrite_existing);
    GTEST_SKIP() << "golden updated: " << goldenPath;
  }
  auto golden = formats::loadImageRgba(goldenPath);
  ASSERT_TRUE(golden) << golden.error() << " (regenerate with GLOBE_UPDATE_GOLDENS=1)";
  const auto difference = globe::testing::compareImages(*golden, *actual, kChannelTolerance);
  if (difference.differingFraction > kMaxDifferingFraction) {
    const fs::path diffPath = outDir / (std::string(view.name) + ".diff.png");
    if (!difference.diffRgba.empty()) {
      (void)formats::writePngAtomically(diffPath, difference.diffRgba, golden->widthPixels,
                                        golden->heightPixels);
    }
    FAIL() << view.name << ": " << 100 * difference.differingFraction
           << "% of pixels differ (max channel " << difference.largestChannelDifference
           << "); actual " << actualPath << ", diff " << diffPath;
  }
  // The image is a real rendering, not an empty frame: it has many distinct colours.
  size_t lit = 0;
  for (size_t p = 0; p < actual->pixels.size(); p += 4) {
    lit += (actual->pixels[p] | actual->pixels[p + 1] | actual->pixels[p + 2]) > 8 ? 1 : 0;
  }
  EXPECT_GT(lit, actual->pixels.size() / 4 / 10) << view.name << " is mostly black";
}

INSTANTIATE_TEST_SUITE_P(Views, GoldenImages, ::testing::ValuesIn(kViews),
                         [](const auto& param) { return std::string(param.param.name); });

TEST(GoldenCompare, DetectsAChangedImage) {
  formats::ImageRgba a{4, 4, std::vector<uint8_t>(64, 100)};
  formats::ImageRgba b = a;
  EXPECT_EQ(globe::testing::compareImages(a, b, 24).differingFraction, 0.0);
  b.pixels[0] = 200;
  const auto d = globe::testing::compareImages(a, b, 24);
  EXPECT_DOUBLE_EQ(d.differingFraction, 1.0 / 16);
  EXPECT_EQ(d.largestChannelDifference, 100);
  EXPECT_EQ(d.diffRgba[0], 255);
  formats::ImageRgba small{2, 2, std::vector<uint8_t>(16, 0)};
  EXPECT_EQ(globe::testing::compareImages(a, small, 24).differingFraction, 1.0);
}

}  // namespace
}  // namespace globe
