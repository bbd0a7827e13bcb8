// The real `globe` over a real nginx on 127.0.0.1: a snapshot of the Zion pyramid with its
// imagery layer read over HTTP is pixel-identical to the local one; with the server stopped,
// --offline from the disk cache gives the same image; a pack that is gone or a location that
// fails still ends with an image of the coarser tiles, one message naming the URL, exit status 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "io/image_io.hpp"
#include "tests/io/nginx_server.hpp"
#include "tests/tools/tiler/imagery_test_layers.hpp"
#include "tests/tools/tiler/tiler_test_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using globe::io::test::NginxServer;

struct ProcessResult {
  int exitCode;
  std::string output;
};

ProcessResult runGlobe(const std::string& arguments) {
  const std::string command = std::string(GLOBE_EXE) + " " + arguments + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer{};
  while (pipe != nullptr && std::fgets(buffer.data(), buffer.size(), pipe) != nullptr)
    output += buffer.data();
  const int status = pipe != nullptr ? ::pclose(pipe) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

// A low oblique view over Zion Canyon: many levels of terrain and imagery.
const std::string kCamera = "--camera -112.95,37.25,4200,20,-25,0 --size 320x200";

std::vector<uint8_t> pixelsOf(const fs::path& png) {
  auto image = globe::io::loadImageRgba(png);
  EXPECT_TRUE(image) << image.error();
  return image ? image->pixels : std::vector<uint8_t>{};
}

size_t differingPixels(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  if (a.size() != b.size()) return SIZE_MAX;
  size_t n = 0;
  for (size_t i = 0; i < a.size(); i += 4) {
    if (a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2]) ++n;
  }
  return n;
}

// The pyramid and the layer copied under one served root (the test damages its copies).
struct Site {
  fs::path dir = globe::tiler::testing::freshTempDir("http-site");
  fs::path root = dir / "www";
  explicit Site() {
    fs::create_directories(root);
    fs::copy(globe::tiler::testing::zionPyramid(), root / "zion", fs::copy_options::recursive);
    fs::copy(globe::tiler::testing::zionLayer(), root / "zion-rgb", fs::copy_options::recursive);
  }
  ~Site() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
};

std::string snapshotArgs(const std::string& pyramid, const std::string& layer,
                         const fs::path& output) {
  return "snapshot " + pyramid + " " + kCamera + " --layer " + layer + " -o " + output.string();
}

TEST(HttpSnapshot, SameImageAsLocalThenOfflineFromTheCache) {
  Site site;
  auto server = NginxServer::start({site.root, ""});
  ASSERT_TRUE(server);
  const fs::path cache = site.dir / "cache";
  const fs::path local = site.dir / "local.png";
  const fs::path remote = site.dir / "remote.png";
  const fs::path offline = site.dir / "offline.png";

  const ProcessResult a = runGlobe(
      snapshotArgs((site.root / "zion").string(), (site.root / "zion-rgb").string(), local));
  ASSERT_EQ(a.exitCode, 0) << a.output;
  const ProcessResult b =
      runGlobe(snapshotArgs(server->url("/zion"), server->url("/zion-rgb"), remote) +
               " --cache-dir " + cache.string());
  ASSERT_EQ(b.exitCode, 0) << b.output;
  const auto localPixels = pixelsOf(local);
  ASSERT_FALSE(localPixels.empty());
  EXPECT_EQ(differingPixels(localPixels, pixelsOf(remote)), 0u);
  // Range requests only: no pack was downloaded whole.
  size_t packRequests = 0;
  for (const std::string& line : server->accessLog()) {
    if (line.find(".pack ") == std::string::npos) continue;
    ++packRequests;
    EXPECT_NE(line.find(" 206 \"bytes="), std::string::npos) << line;
  }
  EXPECT_GT(packRequests, 20u);
  EXPECT_TRUE(fs::exists(cache));

  server->stop();
  const ProcessResult c =
      runGlobe(snapshotArgs(server->url("/zion"), server->url("/zion-rgb"), offline) +
               " --offline --cache-dir " + cache.string());
  ASSERT_EQ(c.exitCode, 0) << c.output;
  EXPECT_EQ(differingPixels(localPixels, pixelsOf(offline)), 0u);

  // Offline with an empty cache: a clear error naming the URL.
  const ProcessResult d =
      runGlobe(snapshotArgs(server->url("/zion"), server->url("/zion-rgb"), site.dir / "none.png") +
               " --offline --cache-dir " + (site.dir / "empty").string());
  EXPECT_EQ(d.exitCode, 1) << d.output;
  EXPECT_NE(d.output.find(server->url("/zion/manifest.json") + ": not in the disk cache"),
            std::string::npos)
      << d.output;
  EXPECT_FALSE(fs::exists(site.dir / "none.png"));
}

TEST(HttpSnapshot, FaultsEndWithAnImageOfCoarserTilesAndOneMessage) {
  Site site;
  // The finest terrain level's packs fail with 500; one imagery pack is gone.
  uint32_t maxLevel = 0;
  for (const auto& e : fs::directory_iterator(site.root / "zion")) {
    const std::string name = e.path().filename().string();
    if (e.is_directory() && name[0] == 'L')
      maxLevel = std::max(maxLevel, static_cast<uint32_t>(std::stoul(name.substr(1))));
  }
  ASSERT_GT(maxLevel, 8u);
  const std::string failing = "/zion/L" + std::to_string(maxLevel) + "/";
  auto server = NginxServer::start({site.root, "location " + failing + " { return 500; }"});
  ASSERT_TRUE(server);
  const fs::path output = site.dir / "fault.png";
  const ProcessResult run =
      runGlobe(snapshotArgs(server->url("/zion"), server->url("/zion-rgb"), output) +
               " --cache-dir " + (site.dir / "cache").string());
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_TRUE(fs::exists(output));
  EXPECT_NE(run.output.find(server->url(failing)), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("HTTP 500; drawing coarser tiles there"), std::string::npos)
      << run.output;
}

}  // namespace
