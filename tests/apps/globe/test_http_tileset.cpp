// A 3D Tiles tileset served by a real nginx on 127.0.0.1: `globe snapshot --tileset URL` draws
// the same image as from the folder, reading only the contents the view needs (the dragon's low
// level from afar, its medium one near; the high file, missing on purpose, is said by its URL and
// the medium one drawn there), and `globe query --tileset URL` reads the same roof.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>

#include "formats/image_io.hpp"
#include "tests/apps/globe/run_globe.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/nginx_server.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using globe::app::test::ProcessResult;
using globe::app::test::runGlobe;
using globe::testing::NginxServer;

const fs::path kDragon =
    fs::path(GLOBE_SOURCE_DIR) / "tests/data/interop/3dtiles/TilesetWithDiscreteLOD";

fs::path flatPyramid() {
  const std::string dem = std::string(GLOBE_SOURCE_DIR) + "/tests/data/dem/";
  return globe::testing::sharedPyramid(
      "flat-philadelphia", {dem + "gtopo30/ETOPO20.DEM", dem + "synthetic/flat-philadelphia.tif"});
}

std::string snapshot(const std::string& camera, const std::string& tileset,
                     const fs::path& output) {
  return "snapshot " + flatPyramid().string() + " --camera " + camera + " --tileset " + tileset +
         " --size 240x135 -o " + output.string();
}

size_t countServed(const std::vector<std::string>& log, const std::string& what) {
  return static_cast<size_t>(std::count_if(log.begin(), log.end(), [&](const std::string& line) {
    return line.find(what) != std::string::npos;
  }));
}

bool samePixels(const fs::path& a, const fs::path& b) {
  auto x = globe::formats::loadImageRgba(a), y = globe::formats::loadImageRgba(b);
  return x && y && x->pixels == y->pixels;
}

TEST(HttpTileset, TheSameDragonFromNginxAsFromTheFolderReadAsTheViewNeedsIt) {
  const fs::path dir = globe::testing::freshTempDir("http-tileset");
  fs::create_directories(dir / "www/dragon");
  fs::copy(kDragon, dir / "www/dragon", fs::copy_options::recursive);
  auto server = NginxServer::start({dir / "www", ""});
  ASSERT_TRUE(server);
  const std::string url = server->url("/dragon/tileset.json");
  const std::string far = "-75.612,40.01,900,0,-5,0", near = "-75.6121,40.0360,450,0,-3,0";

  // From afar: only the low dragon is read.
  const ProcessResult farRun = runGlobe(snapshot(far, url, dir / "far-remote.png"));
  ASSERT_EQ(farRun.exitCode, 0) << farRun.output;
  std::vector<std::string> log = server->accessLog();
  EXPECT_EQ(countServed(log, "GET /dragon/dragon_low.b3dm 200"), 1u);
  EXPECT_EQ(countServed(log, "dragon_medium"), 0u);
  const ProcessResult farLocal = runGlobe(snapshot(far, kDragon.string(), dir / "far-local.png"));
  ASSERT_EQ(farLocal.exitCode, 0) << farLocal.output;
  EXPECT_TRUE(samePixels(dir / "far-remote.png", dir / "far-local.png"));

  // Near: the medium dragon is read; the high one is not there, said by its URL.
  const ProcessResult nearRun = runGlobe(snapshot(near, url, dir / "near-remote.png"));
  ASSERT_EQ(nearRun.exitCode, 0) << nearRun.output;
  EXPECT_NE(nearRun.output.find(server->url("/dragon/dragon_high.b3dm")), std::string::npos)
      << nearRun.output;
  log = server->accessLog();
  EXPECT_EQ(countServed(log, "GET /dragon/dragon_medium.b3dm 200"), 1u);
  const ProcessResult nearLocal =
      runGlobe(snapshot(near, kDragon.string(), dir / "near-local.png"));
  ASSERT_EQ(nearLocal.exitCode, 0) << nearLocal.output;
  EXPECT_TRUE(samePixels(dir / "near-remote.png", dir / "near-local.png"));
  EXPECT_FALSE(samePixels(dir / "near-remote.png", dir / "far-remote.png"));

  // The height service over the same roof: the dragon's back, 300+ m up, either way.
  const std::string point = "echo -75.6121,40.0427 | ";
  const auto query = [&](const std::string& tileset) {
    const std::string command =
        point + GLOBE_EXE + " query " + flatPyramid().string() + " --tileset " + tileset + " 2>&1";
    FILE* pipe = ::popen(command.c_str(), "r");
    std::string out;
    char buffer[512];
    while (pipe != nullptr && std::fgets(buffer, sizeof buffer, pipe) != nullptr) out += buffer;
    if (pipe != nullptr) ::pclose(pipe);
    return out;
  };
  const std::string remote = query(url), local = query(kDragon.string());
  const std::string remoteLine = remote.substr(remote.rfind("-75.6121"));
  EXPECT_EQ(remoteLine, local.substr(local.rfind("-75.6121"))) << remote << local;
  std::istringstream fields(remoteLine);
  std::string field;
  for (int k = 0; k < 4; ++k) std::getline(fields, field, ',');
  EXPECT_GT(std::stod(field), 300.0) << remoteLine;
  fs::remove_all(dir);
}

}  // namespace
