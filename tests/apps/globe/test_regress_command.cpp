// globe regress as a user runs it: the real program over the bundled pyramid and the bundled Fuji
// overlay, a suite whose paths are relative to its folder. References written by --update, an
// unchanged suite passing, a changed overlay colour failing that view alone with its images,
// --update rewriting only that reference, and the errors that must never pass: no reference, a
// missing pyramid, tiles that fail, a run past its budget, a bad suite.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/apps/globe/run_globe.hpp"
#include "tests/support/damaged_pyramid.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;
using test::runGlobe;

std::string readText(const fs::path& file) {
  std::stringstream text;
  text << std::ifstream(file, std::ios::binary).rdbuf();
  return text.str();
}

void writeText(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// Two views at 240x135: the bundled pyramid (linked in as "pyramid") and the Fuji overlay beside
// the suite, both named relative to it.
fs::path makeSuite(const fs::path& dir) {
  fs::create_directories(dir);
  fs::create_directory_symlink(globe::testing::bundledPyramid(), dir / "pyramid");
  fs::copy_file(fs::path(GLOBE_SOURCE_DIR) / "data/overlays/fuji-demo.kml",
                dir / "overlay.kml");
  writeText(dir / "suite.json", R"({"views": [
    {"name": "fuji", "snapshot": ["pyramid", "--camera", "138.60,35.20,6000,30,-15,0",
                                  "--size", "240x135"]},
    {"name": "fuji_overlay", "snapshot": ["pyramid", "--camera", "138.80,35.25,9000,315,-25,0",
                                          "--overlay", "overlay.kml", "--size", "240x135"]}]})");
  return dir / "suite.json";
}

nlohmann::json statuses(const fs::path& out) {
  const auto report = nlohmann::json::parse(readText(out / "report.json"));
  nlohmann::json byName;
  for (const auto& view : report["views"]) byName[view["name"].get<std::string>()] = view;
  return byName;
}

std::string regress(const fs::path& suite, const fs::path& out, const std::string& more = "") {
  const bool jobsGiven = more.find("--jobs") != std::string::npos;
  return "regress " + suite.string() + " --out " + out.string() + (jobsGiven ? " " : " --jobs 2 ") +
         more;
}

TEST(GlobeRegress, ReferencesThenPassThenOneChangedViewFailsAloneThenUpdateRewritesOnlyIt) {
  const fs::path dir = globe::testing::freshTempDir("regress-suite");
  const fs::path suite = makeSuite(dir / "suite");
  const fs::path out = dir / "out";

  auto run = runGlobe(regress(suite, out));
  EXPECT_EQ(run.exitCode, 2) << "no references yet: errors, not passes\n" << run.output;
  EXPECT_NE(run.output.find("--update writes it"), std::string::npos) << run.output;

  run = runGlobe(regress(suite, out, "--update"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(statuses(out)["fuji"]["status"], "updated");
  EXPECT_EQ(statuses(out)["fuji_overlay"]["message"], "new reference written");
  const std::string fujiReference = readText(dir / "suite/references/fuji.png");
  ASSERT_FALSE(fujiReference.empty());

  run = runGlobe(regress(suite, out));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  auto views = statuses(out);
  EXPECT_EQ(views["fuji"]["status"], "pass");
  EXPECT_EQ(views["fuji"]["differingFraction"], 0.0) << "a snapshot is deterministic";
  EXPECT_EQ(views["fuji_overlay"]["ssim"], 1.0);
  EXPECT_FALSE(fs::exists(out / "fuji.actual.png")) << "a pass leaves no images";

  // The overlay's lines recoloured: that view fails, with its three images and the report's.
  std::string kml = readText(dir / "suite/overlay.kml");
  size_t changed = 0;
  for (size_t at = kml.find("<color>"); at != std::string::npos; at = kml.find("<color>", at + 1)) {
    kml.replace(at + 7, 8, "ff00ff00");  // aabbggrr: opaque green
    ++changed;
  }
  ASSERT_GT(changed, 0u);
  writeText(dir / "suite/overlay.kml", kml);
  run = runGlobe(regress(suite, out));
  EXPECT_EQ(run.exitCode, 1) << run.output;
  views = statuses(out);
  EXPECT_EQ(views["fuji"]["status"], "pass");
  EXPECT_EQ(views["fuji_overlay"]["status"], "fail");
  EXPECT_GT(views["fuji_overlay"]["differingFraction"].get<double>(), 0.001);
  for (const char* image : {"expected", "actual", "diff"}) {
    EXPECT_TRUE(fs::exists(out / (std::string("fuji_overlay.") + image + ".png"))) << image;
  }
  EXPECT_NE(readText(out / "report.html").find("fuji_overlay.diff.png"), std::string::npos);
  tinyxml2::XMLDocument junit;
  ASSERT_EQ(junit.LoadFile((out / "junit.xml").c_str()), tinyxml2::XML_SUCCESS);
  const auto* junitSuite = junit.FirstChildElement("testsuites")->FirstChildElement("testsuite");
  EXPECT_STREQ(junitSuite->Attribute("failures"), "1");

  run = runGlobe(regress(suite, out, "--update"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  views = statuses(out);
  EXPECT_EQ(views["fuji"]["status"], "pass") << "unchanged: its reference left alone";
  EXPECT_EQ(views["fuji_overlay"]["status"], "updated");
  EXPECT_EQ(readText(dir / "suite/references/fuji.png"), fujiReference);
  EXPECT_FALSE(fs::exists(out / "fuji_overlay.diff.png")) << "no stale images of a fixed view";
  EXPECT_EQ(runGlobe(regress(suite, out)).exitCode, 0);
  EXPECT_EQ(runGlobe(regress(suite, out, "--filter '^fuji$'")).exitCode, 0);
  EXPECT_EQ(statuses(out).size(), 1u) << "--filter ran one view";
}

// One worker draws the three views one after another (--jobs 1): each image is byte for byte
// what `globe snapshot` alone draws, so nothing of one view reaches the next.
TEST(GlobeRegress, OneWorkerDrawsEachViewAsItsOwnSnapshotWould) {
  const fs::path dir = globe::testing::freshTempDir("regress-worker");
  const fs::path suite = makeSuite(dir / "suite");
  const std::string plain = "--camera 138.60,35.20,6000,30,-15,0 --size 240x135";
  const std::string overlaid = "--camera 138.80,35.25,9000,315,-25,0 --size 240x135 --overlay " +
                               (dir / "suite/overlay.kml").string();
  writeText(suite, R"({"views": [
    {"name": "fuji", "snapshot": ["pyramid", "--camera", "138.60,35.20,6000,30,-15,0",
                                  "--size", "240x135"]},
    {"name": "fuji_overlay", "snapshot": ["pyramid", "--camera", "138.80,35.25,9000,315,-25,0",
                                          "--overlay", "overlay.kml", "--size", "240x135"]},
    {"name": "fuji_again", "snapshot": ["pyramid", "--camera", "138.60,35.20,6000,30,-15,0",
                                        "--size", "240x135"]}]})");
  const auto run = runGlobe(regress(suite, dir / "out", "--update --jobs 1"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const std::string pyramid = globe::testing::bundledPyramid().string();
  const std::pair<std::string, std::string> views[] = {
      {"fuji", plain}, {"fuji_overlay", overlaid}, {"fuji_again", plain}};
  for (const auto& [name, arguments] : views) {
    const fs::path single = dir / (name + ".single.png");
    const auto alone = runGlobe("snapshot " + pyramid + " " + arguments + " -o " + single.string());
    ASSERT_EQ(alone.exitCode, 0) << alone.output;
    EXPECT_EQ(readText(dir / "suite/references" / (name + ".png")), readText(single))
        << name << ": drawn by the worker differs from its own snapshot";
  }
}

// The worker's protocol: an answer for every line, and what is not a snapshot request refused.
TEST(GlobeSnapshotWorker, AnswersEveryRequestAndRefusesWhatIsNotASnapshot) {
  const fs::path dir = globe::testing::freshTempDir("snapshot-worker");
  const auto request = [&](const std::string& folder, const std::string& name,
                           std::vector<std::string> arguments) {
    return nlohmann::json{{"folder", folder}, {"log", (dir / (name + ".log")).string()},
                          {"arguments", arguments}}.dump() + "\n";
  };
  const std::string pyramid = globe::testing::bundledPyramid().string();
  const std::vector<std::string> view = {"snapshot", pyramid, "--camera", "138.7,35.3,9000",
                                         "--size", "64x36", "-o", (dir / "a.png").string()};
  writeText(dir / "requests", request(dir.string(), "a", view) + "not json\n" +
                                  request(dir.string(), "b", {"info", pyramid}) +
                                  request("/nonexistent-folder", "c", view));
  const auto run = runGlobe("snapshot-worker < " + (dir / "requests").string());
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(run.output.find("{\"exit\": 0}"), run.output.rfind("{\"exit\": 0}")) << run.output;
  size_t refused = 0;
  for (size_t at = run.output.find("{\"exit\": 2}"); at != std::string::npos;
       at = run.output.find("{\"exit\": 2}", at + 1)) {
    ++refused;
  }
  EXPECT_EQ(refused, 3u) << run.output;
  EXPECT_NE(run.output.find("{\"exit\": 0}"), std::string::npos) << run.output;
  EXPECT_NE(readText(dir / "a.log").find(" tiles drawn"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "a.png"));
  for (const char* reason : {"is not {folder, log, arguments}", "runs `snapshot` only",
                             "/nonexistent-folder: No such file or directory"}) {
    EXPECT_NE(run.output.find(reason), std::string::npos) << reason << "\n" << run.output;
  }
}

TEST(GlobeRegress, ViewsThatCannotRenderAreErrorsNeverPasses) {
  const fs::path dir = globe::testing::freshTempDir("regress-errors");
  const fs::path damaged = globe::testing::damagedPyramid(dir);
  writeText(dir / "suite.json", R"({"views": [
    {"name": "no_pyramid", "snapshot": ["missing-pyramid", "--camera", "138.7,35.3,6000"]},
    {"name": "failed_tiles", "snapshot": [")" + damaged.string() + R"(",
      "--camera", "138.72,35.33,4500,20,-60,0", "--size", "240x135"]},
    {"name": "bad_camera", "snapshot": ["missing-pyramid", "--camera", "north"]}]})");
  const fs::path out = dir / "out";
  // Even --update writes no reference for a view that did not render.
  const auto run = runGlobe(regress(dir / "suite.json", out, "--update"));
  EXPECT_EQ(run.exitCode, 2) << run.output;
  auto views = statuses(out);
  for (const char* name : {"no_pyramid", "failed_tiles", "bad_camera"}) {
    EXPECT_EQ(views[name]["status"], "error") << name;
    EXPECT_TRUE(views[name]["differingFraction"].is_null()) << name;
    EXPECT_FALSE(fs::exists(dir / "references" / (std::string(name) + ".png"))) << name;
  }
  EXPECT_NE(views["no_pyramid"]["message"].get<std::string>().find("missing-pyramid"),
            std::string::npos) << views["no_pyramid"];
  EXPECT_NE(views["failed_tiles"]["message"].get<std::string>().find("failed to load"),
            std::string::npos) << views["failed_tiles"];
}

TEST(GlobeRegress, ARunPastItsBudgetEndsItsViewsAsErrors) {
  const fs::path dir = globe::testing::freshTempDir("regress-budget");
  const fs::path suite = makeSuite(dir / "suite");
  const auto run = runGlobe(regress(suite, dir / "out", "--update --jobs 1 --budget 0.001"));
  EXPECT_EQ(run.exitCode, 2) << run.output;
  const nlohmann::json views = statuses(dir / "out");
  ASSERT_EQ(views.size(), 2u);
  for (const auto& [name, view] : views.items()) {
    EXPECT_EQ(view["status"], "error") << name;
  }
  EXPECT_FALSE(fs::exists(dir / "suite/references")) << "nothing rendered, nothing written";
}

TEST(GlobeRegress, ABadSuiteOrFilterIsExitTwoWithTheReason) {
  const fs::path dir = globe::testing::freshTempDir("regress-bad");
  writeText(dir / "suite.json", R"({"views": [{"name": "a", "snapshot": ["p", "-o", "x.png"]}]})");
  auto run = runGlobe(regress(dir / "suite.json", dir / "out"));
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("suite.json: view 1 (a): \"snapshot\" must not give -o"),
            std::string::npos) << run.output;
  writeText(dir / "good.json", R"({"views": [{"name": "a", "snapshot": ["p"]}]})");
  run = runGlobe(regress(dir / "good.json", dir / "out", "--filter '(unclosed'"));
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("is not a regular expression"), std::string::npos) << run.output;
  run = runGlobe(regress(dir / "good.json", dir / "out", "--filter zzz"));
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("selects no view"), std::string::npos) << run.output;
  run = runGlobe(regress(dir / "good.json", dir / "out", "--jobs 0"));
  EXPECT_EQ(run.exitCode, 2) << "a bad option is exit 2 too, not CLI11's own code\n" << run.output;
  EXPECT_EQ(runGlobe("regress --help").exitCode, 0);
}

}  // namespace
}  // namespace globe::app
