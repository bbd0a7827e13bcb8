// The real `globe` over a real nginx on 127.0.0.1: a snapshot of the Zion pyramid with its
// imagery layer read over HTTP is pixel-identical to the local one; with the server stopped,
// --offline from the disk cache gives the same image; a pack that is gone or a location that
// fails still ends with an image of the coarser tiles, one message naming the URL, exit status 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "formats/image_io.hpp"
#include "tests/apps/globe/run_globe.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/nginx_server.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using globe::testing::NginxServer;

using globe::app::test::ProcessResult;
using globe::app::test::runGlobe;

// A low oblique view over Zion Canyon: many levels of terrain and imagery.
const std::string kCamera = "--camera -112.95,37.25,4200,20,-25,0 --size 320x200";

std::vector<uint8_t> pixelsOf(const fs::path& png) {
  auto image = globe::formats::loadImageRgba(png);
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
  fs::path dir = globe::testing::freshTempDir("http-site");
  fs::path root = dir / "www";
  explicit Site() {
    fs::create_directories(root);
    fs::copy(globe::testing::zionPyramid(), root / "zion", fs::copy_options::recursive);
    fs::copy(globe::testing::zionLayer(), root / "zion-rgb", fs::copy_options::recursive);
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

// Two viewers at once on one cache directory (cold): both images are the local one, and a third
// run offline from that cache is too.
TEST(HttpSnapshot, TwoProcessesShareOneCache) {
  Site site;
  auto server = NginxServer::start({site.root, ""});
  ASSERT_TRUE(server);
  const fs::path cache = site.dir / "shared-cache";
  const fs::path local = site.dir / "local.png";
  ASSERT_EQ(runGlobe(snapshotArgs((site.root / "zion").string(), (site.root / "zion-rgb").string(),
                                  local))
                .exitCode,
            0);
  ProcessResult runs[2];
  std::thread other([&] {
    runs[1] =
        runGlobe(snapshotArgs(server->url("/zion"), server->url("/zion-rgb"), site.dir / "b.png") +
                 " --cache-dir " + cache.string());
  });
  runs[0] =
      runGlobe(snapshotArgs(server->url("/zion"), server->url("/zion-rgb"), site.dir / "a.png") +
               " --cache-dir " + cache.string());
  other.join();
  ASSERT_EQ(runs[0].exitCode, 0) << runs[0].output;
  ASSERT_EQ(runs[1].exitCode, 0) << runs[1].output;
  const auto pixels = pixelsOf(local);
  EXPECT_EQ(differingPixels(pixels, pixelsOf(site.dir / "a.png")), 0u);
  EXPECT_EQ(differingPixels(pixels, pixelsOf(site.dir / "b.png")), 0u);
  server->stop();
  const ProcessResult offline =
      runGlobe(snapshotArgs(server->url("/zion"), server->url("/zion-rgb"), site.dir / "c.png") +
               " --offline --cache-dir " + cache.string());
  ASSERT_EQ(offline.exitCode, 0) << offline.output;
  EXPECT_EQ(differingPixels(pixels, pixelsOf(site.dir / "c.png")), 0u);
}

uint32_t finestLevel(const fs::path& pyramid) {
  uint32_t maxLevel = 0;
  for (const auto& e : fs::directory_iterator(pyramid)) {
    const std::string name = e.path().filename().string();
    if (e.is_directory() && name[0] == 'L') {
      maxLevel = std::max(maxLevel, static_cast<uint32_t>(std::stoul(name.substr(1))));
    }
  }
  return maxLevel;
}

size_t blackPixels(const std::vector<uint8_t>& rgba) {
  size_t n = 0;
  for (size_t i = 0; i < rgba.size(); i += 4) n += rgba[i] + rgba[i + 1] + rgba[i + 2] == 0 ? 1 : 0;
  return n;
}

// A level that fails on the server (500 after the retries, or a response so slow it times out)
// draws exactly what the local pyramid draws when that level is never loaded (its parents);
// one message names the level's URL and the problem; the image is written, and the exit status
// is 1 (tiles are missing from it) unless --allow-missing says that is fine.
TEST(HttpSnapshot, AFailingLevelDrawsItsParentsWithOneMessage) {
  Site site;
  const uint32_t finest = finestLevel(site.root / "zion");
  ASSERT_GT(finest, 8u);
  const std::string failing = "/zion/L" + std::to_string(finest) + "/";
  const fs::path reference = site.dir / "reference.png";
  const ProcessResult local = runGlobe(
      snapshotArgs((site.root / "zion").string(), (site.root / "zion-rgb").string(), reference) +
      " --max-load-level " + std::to_string(finest - 1));
  ASSERT_EQ(local.exitCode, 0) << local.output;
  struct Fault {
    std::string directive;
    std::string message;
  };
  for (const Fault& fault : {Fault{"return 500;", "HTTP 500; drawing coarser tiles there"},
                             Fault{"limit_rate 20;", "timed out"}}) {
    SCOPED_TRACE(fault.directive);
    auto server =
        NginxServer::start({site.root, "location " + failing + " { " + fault.directive + " }"});
    ASSERT_TRUE(server);
    const fs::path output = site.dir / "fault.png";
    fs::remove(output);
    const ProcessResult run =
        runGlobe(snapshotArgs(server->url("/zion"), server->url("/zion-rgb"), output) +
                 " --http-timeout 2 --cache-dir " + (site.dir / "cache-fault").string());
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("--allow-missing accepts such an image"), std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find(server->url(failing)), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(fault.message), std::string::npos) << run.output;
    EXPECT_EQ(differingPixels(pixelsOf(reference), pixelsOf(output)), 0u);
  }
}

// A pack deleted or truncated on the server draws what the local pyramid with the same damage
// draws (the pack's parents); one message names the pack's URL.
TEST(HttpSnapshot, ADamagedPackDrawsWhatTheSameDamageDrawsLocally) {
  Site site;
  const uint32_t finest = finestLevel(site.root / "zion");
  // The finest pack under the camera (-112.95, 37.25): level L has 2^(L+1) x 2^L tiles, 64 a pack.
  const double tilesPerDegree = std::ldexp(1.0, static_cast<int>(finest)) / 180.0;
  const auto x = static_cast<uint32_t>((-112.95 + 180.0) * tilesPerDegree) / 64;
  const auto y = static_cast<uint32_t>((90.0 - 37.25) * tilesPerDegree) / 64;
  const std::string pack =
      "L" + std::to_string(finest) + "/" + std::to_string(x) + "_" + std::to_string(y) + ".pack";
  ASSERT_TRUE(fs::exists(site.root / "zion" / pack)) << pack;
  const fs::path whole = site.dir / "whole.png";
  ASSERT_EQ(runGlobe(snapshotArgs((site.root / "zion").string(), (site.root / "zion-rgb").string(),
                                  whole))
                .exitCode,
            0);
  for (const std::string damage : {"deleted", "truncated"}) {
    SCOPED_TRACE(damage);
    const fs::path copy = site.dir / ("zion-" + damage);
    fs::remove_all(copy);
    fs::copy(site.root / "zion", copy, fs::copy_options::recursive);
    if (damage == "deleted") {
      fs::remove(copy / pack);
    } else {
      fs::resize_file(copy / pack, fs::file_size(copy / pack) / 2);
    }
    fs::create_symlink(copy, site.root / ("zion-" + damage));
    const fs::path local = site.dir / "local.png";
    const fs::path remote = site.dir / "remote.png";
    const ProcessResult a = runGlobe(
        snapshotArgs(copy.string(), (site.root / "zion-rgb").string(), local) + " --allow-missing");
    ASSERT_EQ(a.exitCode, 0) << a.output;
    auto server = NginxServer::start({site.root, ""});
    ASSERT_TRUE(server);
    const ProcessResult b =
        runGlobe(snapshotArgs(server->url("/zion-" + damage), server->url("/zion-rgb"), remote) +
                 " --cache-dir " + (site.dir / ("cache-" + damage)).string());
    EXPECT_EQ(b.exitCode, 1) << "a pack is missing from the image\n" << b.output;
    EXPECT_NE(b.output.find(server->url("/zion-" + damage + "/" + pack)), std::string::npos)
        << b.output;
    EXPECT_EQ(differingPixels(pixelsOf(local), pixelsOf(remote)), 0u);
    EXPECT_GT(differingPixels(pixelsOf(whole), pixelsOf(remote)), 0u);  // the damage shows
  }
}

// The server stops while the snapshot loads: it still ends with an image (what had arrived, and
// the parents of what had not) and a message naming the URL.
TEST(HttpSnapshot, AServerStoppedMidFlightStillEndsWithAnImage) {
  Site site;
  auto server = NginxServer::start({site.root, "location /zion/ { limit_rate 10k; }"});
  ASSERT_TRUE(server);
  const fs::path output = site.dir / "stopped.png";
  const std::string command = std::string(GLOBE_EXE) + " " +
                              snapshotArgs(server->url("/zion"), server->url("/zion-rgb"), output) +
                              " --no-sky --http-timeout 5 --cache-dir " +
                              (site.dir / "cache").string() + " > " +
                              (site.dir / "stopped.log").string() + " 2>&1";
  std::thread snapshot([&] { (void)std::system(command.c_str()); });
  // Stop once some blocks have arrived (every request of the run is logged when answered).
  for (int i = 0; i < 2000 && server->accessLog().size() < 30; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const size_t served = server->accessLog().size();
  server->stop();
  snapshot.join();
  std::ifstream in(site.dir / "stopped.log");
  const std::string log{std::istreambuf_iterator<char>(in), {}};
  EXPECT_GE(served, 30u) << log;
  ASSERT_TRUE(fs::exists(output)) << log;
  EXPECT_NE(log.find(server->url("/zion/")), std::string::npos) << log;
  EXPECT_NE(log.find("drawing coarser tiles there"), std::string::npos) << log;
  // Coarser, not holes: without the sky, a hole is black like space; the image has no more black
  // than the complete one, but for the coarser horizon (1 % of the pixels).
  const fs::path whole = site.dir / "whole.png";
  ASSERT_EQ(runGlobe(snapshotArgs((site.root / "zion").string(), (site.root / "zion-rgb").string(),
                                  whole) +
                     " --no-sky")
                .exitCode,
            0);
  const auto complete = pixelsOf(whole);
  const auto stopped = pixelsOf(output);
  ASSERT_EQ(complete.size(), stopped.size());
  EXPECT_GT(differingPixels(complete, stopped), complete.size() / 40);  // it is coarser
  EXPECT_LE(blackPixels(stopped), blackPixels(complete) + complete.size() / 4 / 100);
}

}  // namespace

// A hostile server (tests/support/stalling_server.py on 127.0.0.1, gone by itself after 60 s)
// behind every URL: each way of stalling ends the snapshot within its deadline, exit 1, the URL
// named with the reason. A body announced as 10^12 bytes is refused at its headers; a server
// that never answers or trickles fails each request in two tries of --http-timeout.
TEST(HttpSnapshot, AStallingServerFailsWithinTheDeadline) {
  const fs::path dir = globe::testing::freshTempDir("http-stall");
  const std::string server = std::string(GLOBE_SOURCE_DIR) + "/tests/support/stalling_server.py";
  struct Case {
    std::string mode;
    std::string message;
    double withinSeconds;
  };
  for (const Case& c : {Case{"huge", "larger than", 3.0},
                        Case{"silent", "timed out", 6.0}, Case{"trickle", "timed out", 6.0}}) {
    SCOPED_TRACE(c.mode);
    const fs::path portFile = dir / (c.mode + ".port");
    const std::string start = "python3 " + server + " " + c.mode + " --lifetime 60 --port-file " +
                              portFile.string() + " >/dev/null 2>&1 &";
    ASSERT_EQ(std::system(start.c_str()), 0);
    for (int i = 0; i < 200 && !fs::exists(portFile); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(25));  // until it listens
    }
    std::string port;
    std::ifstream(portFile) >> port;
    ASSERT_FALSE(port.empty()) << "the server did not start";
    const std::string url = "http://127.0.0.1:" + port + "/zion";
    const auto began = std::chrono::steady_clock::now();
    const ProcessResult run = runGlobe("snapshot " + url + " " + kCamera + " -o " +
                                       (dir / "out.png").string() +
                                       " --http-timeout 1 --cache-dir " + (dir / "cache").string());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find(url), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << run.output;
    EXPECT_LT(seconds, c.withinSeconds) << run.output;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
  }
}
