// `globe path check` over the bundled pyramid: a path kept well above Fuji is clear (exit 0); the
// same path with a keyframe put into the summit is reported under the terrain around that
// keyframe's time, and one skimming 1 m above the ground nearer than the 2 m clearance (exit 1);
// bad arguments exit 2.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;

struct CheckRun {
  int exitCode = -1;
  std::string output;
};

CheckRun check(const fs::path& path, const std::string& extra = "") {
  const fs::path log = path.string() + ".txt";
  const std::string command = std::string(GLOBE_EXE) + " path check " +
                              globe::testing::bundledPyramid().string() + " " + path.string() +
                              " " + extra + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::stringstream text;
  text << std::ifstream(log).rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

fs::path writePath(const fs::path& dir, const std::string& name, double middleHeight,
                   bool aboveTerrain = false) {
  const fs::path file = dir / name;
  const std::string above = aboveTerrain ? ", \"aboveTerrain\": true" : "";
  std::ofstream(file) << R"({"interpolation": "linear", "keyframes": [
    {"t": 0, "lon": 138.60, "lat": 35.36, "height": 6000, "pitch": -20},
    {"t": 10, "lon": 138.7274, "lat": 35.3606, "height": )"
                      << middleHeight << above << R"(, "pitch": -20},
    {"t": 20, "lon": 138.85, "lat": 35.36, "height": 6000, "pitch": -20}]})";
  return file;
}

TEST(PathCheck, FindsTheDipPutIntoAPathAndPassesAClearOne) {
  const fs::path dir = globe::testing::freshTempDir("path-check");
  const CheckRun clear = check(writePath(dir, "clear.json", 6000));
  EXPECT_EQ(clear.exitCode, 0) << clear.output;
  EXPECT_NE(clear.output.find("clear: the path keeps 2 m above the terrain everywhere"),
            std::string::npos)
      << clear.output;
  EXPECT_NE(clear.output.find("20.00 s, 601 samples"), std::string::npos) << clear.output;

  // The middle keyframe 800 m below the summit (3,776 m): under the terrain around t = 10 s.
  const CheckRun dip = check(writePath(dir, "dip.json", 2976));
  EXPECT_EQ(dip.exitCode, 1) << dip.output;
  const size_t under = dip.output.find("under the terrain: ");
  ASSERT_NE(under, std::string::npos) << dip.output;
  const double from = std::stod(dip.output.substr(under + 19));
  const double to = std::stod(dip.output.substr(dip.output.find('-', under + 19) + 1));
  EXPECT_LT(from, 10.0);
  EXPECT_GT(to, 10.0);
  // About 800 m under the summit (3,732 m in the bundled 3" DEM's grid: 756 m).
  const size_t deepest = dip.output.find("deepest ");
  ASSERT_NE(deepest, std::string::npos) << dip.output;
  const double depth = std::stod(dip.output.substr(deepest + 8));
  EXPECT_LT(depth, -700.0) << dip.output;
  EXPECT_GT(depth, -850.0) << dip.output;

  // 1 m above the summit: nearer than the clearance, not under.
  const CheckRun skim = check(writePath(dir, "skim.json", 1, true));
  EXPECT_EQ(skim.exitCode, 1) << skim.output;
  EXPECT_NE(skim.output.find("nearer than 2 m: "), std::string::npos) << skim.output;
  EXPECT_EQ(skim.output.find("under the terrain"), std::string::npos) << skim.output;
  const CheckRun lower = check(writePath(dir, "skim2.json", 1, true), "--clearance 0.5");
  EXPECT_EQ(lower.exitCode, 0) << lower.output;

  const CheckRun badRate = check(writePath(dir, "rate.json", 6000), "--rate 0");
  EXPECT_EQ(badRate.exitCode, 2) << badRate.output;
  const CheckRun missing = check(dir / "none.json");
  EXPECT_EQ(missing.exitCode, 1) << missing.output;
  EXPECT_NE(missing.output.find("none.json"), std::string::npos) << missing.output;
}

}  // namespace
}  // namespace globe::app
