// Screenshot regression of the project's own pictures, through the product's runner: the views of
// tests/render/golden_suite.json (the bundled real data, imagery layers, the water mask,
// overlays, the sky) drawn by `globe regress` and compared with tests/render/golden (24/255 per
// channel on at most 0.5% of pixels, SSIM at least 0.98). One test per view (`--filter`), so CTest
// runs them in parallel. The suite names its inputs relative to a folder this test fills with
// links: pyramid, zion-pyramid, flat-pyramid, layers/{bm,zion,coast} (tiled once per CTest run),
// repo (the checkout) and references (tests/render/golden). Regenerate (then look at them!) with:
//   GLOBE_UPDATE_GOLDENS=1 ctest --test-dir build -R globe_golden_tests
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/apps/globe/run_globe.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe {
namespace {

namespace fs = std::filesystem;

fs::path suiteFile() { return fs::path(GLOBE_SOURCE_DIR) / "tests/render/golden_suite.json"; }

std::vector<std::string> viewNames() {
  std::ifstream in(suiteFile());
  const auto suite = nlohmann::json::parse(in, nullptr, false);
  std::vector<std::string> names;
  if (suite.is_discarded()) return {"the_suite_is_not_valid_json"};
  for (const auto& view : suite["views"]) names.push_back(view["name"].get<std::string>());
  return names;
}

// ETOPO20 with flat ground at 0.01 m around Philadelphia, where the 3D Tiles samples stand.
fs::path flatPyramid() {
  const std::string dem = std::string(GLOBE_SOURCE_DIR) + "/tests/data/dem/";
  return globe::testing::sharedPyramid(
      "flat-philadelphia", {dem + "gtopo30/ETOPO20.DEM", dem + "synthetic/flat-philadelphia.tif"});
}

// The folder the suite runs in: links to what its views name.
fs::path suiteFolder() {
  const fs::path folder = globe::testing::freshTempDir("golden-suite");
  const std::pair<const char*, fs::path> links[] = {
      {"pyramid", globe::testing::bundledPyramid()},
      {"zion-pyramid", globe::testing::zionPyramid()},
      {"flat-pyramid", flatPyramid()},
      {"layers/bm", globe::testing::blueMarbleLayer()},
      {"layers/zion", globe::testing::zionLayer()},
      {"layers/coast", globe::testing::coastMask()},
      {"repo", GLOBE_SOURCE_DIR},
      {"references", fs::path(GLOBE_SOURCE_DIR) / "tests/render/golden"}};
  fs::create_directories(folder / "layers");
  for (const auto& [name, target] : links) fs::create_directory_symlink(target, folder / name);
  fs::copy_file(suiteFile(), folder / "suite.json");
  return folder;
}

class GoldenImages : public ::testing::TestWithParam<std::string> {};

TEST_P(GoldenImages, MatchesTheCommittedGolden) {
  const std::string& name = GetParam();
  const fs::path folder = suiteFolder();
  const fs::path out = fs::path(globe::build_paths::binaryDir()) / "tests/render/golden-output";
  const bool update = std::getenv("GLOBE_UPDATE_GOLDENS") != nullptr;
  const auto run = app::test::runGlobe("regress " + (folder / "suite.json").string() + " --out " +
                                       (out / name).string() + " --jobs 1 --filter '^" + name +
                                       "$'" + (update ? " --update" : ""));
  EXPECT_EQ(run.exitCode, 0) << run.output << "report: " << (out / name / "report.html");
  if (update) GTEST_SKIP() << "golden updated where it changed: " << run.output;
}

INSTANTIATE_TEST_SUITE_P(Views, GoldenImages, ::testing::ValuesIn(viewNames()),
                         [](const auto& param) { return param.param; });

}  // namespace
}  // namespace globe
