// Resumability and atomicity: a tiler killed at random moments and re-run yields a pyramid
// identical to an uninterrupted run; damaged or foreign outputs are handled with clear errors.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <random>
#include <thread>

#include "formats/pyramid_manifest.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "tiling/tiler.hpp"

namespace globe::tiling {
namespace {

namespace fs = std::filesystem;

using globe::testing::checksums;

// Runs the real globe-tiler executable; returns its pid.
pid_t spawnTiler(const fs::path& out, const std::vector<std::string>& inputs) {
  std::vector<std::string> args = {GLOBE_TILER_EXE, "-q", "-o", out.string()};
  args.insert(args.end(), inputs.begin(), inputs.end());
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, STDOUT_FILENO);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

int waitExit(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

size_t countPacks(const fs::path& dir) {
  size_t count = 0;
  std::error_code error;
  for (auto it = fs::recursive_directory_iterator(dir, error);
       !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
    count += it->path().extension() == ".pack" ? 1 : 0;
  }
  return count;
}

TEST(TilerResume, KilledAtRandomMomentsThenRerunGivesAnIdenticalPyramid) {
  const auto reference = checksums(globe::testing::bundledPyramid());
  ASSERT_GT(reference.size(), 20u);
  const fs::path out = globe::testing::freshTempDir("killed") / "pyramid";

  // Each attempt is killed a random few milliseconds after it finished a new pack, so kills land
  // mid-run (often mid-write) whatever the machine's speed; every run resumes the previous one.
  std::mt19937 random(20261120);
  int killedMidway = 0;
  for (int attempt = 0; attempt < 8; ++attempt) {
    const size_t before = countPacks(out);
    const pid_t pid = spawnTiler(out, globe::testing::bundledInputs());
    int status = 0;
    bool exited = false;
    while (!(exited = ::waitpid(pid, &status, WNOHANG) == pid) && countPacks(out) <= before) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    if (exited) continue;
    std::this_thread::sleep_for(
        std::chrono::microseconds(std::uniform_int_distribution<int>(0, 20000)(random)));
    ::kill(pid, SIGKILL);
    killedMidway += waitExit(pid) == 128 + SIGKILL ? 1 : 0;
  }
  EXPECT_GE(killedMidway, 4) << "the kills should land while the tiler runs";
  ASSERT_EQ(waitExit(spawnTiler(out, globe::testing::bundledInputs())), 0);
  EXPECT_EQ(checksums(out), reference);
}

TEST(TilerResume, DamagedPacksAndStaleTemporariesAreRepaired) {
  const fs::path out = globe::testing::freshTempDir("damaged") / "pyramid";
  fs::copy(globe::testing::bundledPyramid(), out, fs::copy_options::recursive);
  const auto reference = checksums(out);
  const auto finest = std::find_if(reference.begin(), reference.end(),
                                   [](const auto& file) { return file.first.starts_with("L14/"); });
  ASSERT_NE(finest, reference.end());
  ASSERT_TRUE(fs::remove(out / finest->first));  // a finest-level pack
  fs::remove(out / "manifest.json");
  fs::resize_file(out / "L3" / "0_0.pack", 1000);  // truncated by a crash of the disk
  { std::ofstream(out / "L5" / "0_0.pack.tmp-1-1") << "half a pack"; }
  fs::remove(out / "L7" / "1_0.pack");
  fs::create_symlink("1_0.pack", out / "L7" / "1_0.pack");  // a loop: cannot even be stat'ed
  TilerOptions options;
  options.inputs = globe::testing::bundledInputs();
  options.outputDir = out;
  auto report = runTiler(options);
  ASSERT_TRUE(report) << report.error();
  EXPECT_EQ(report->packsBuilt, 3u);
  EXPECT_EQ(checksums(out), reference);
}

TEST(TilerResume, RefusesADirectoryMadeFromOtherInputs) {
  const fs::path out = globe::testing::freshTempDir("foreign") / "pyramid";
  fs::copy(globe::testing::bundledPyramid(), out, fs::copy_options::recursive);
  TilerOptions options;
  options.inputs = {globe::testing::bundledInputs()[0]};
  options.outputDir = out;
  auto report = runTiler(options);
  ASSERT_FALSE(report);
  EXPECT_NE(report.error().find("other inputs or options"), std::string::npos) << report.error();
}

TEST(TilerErrors, MissingAndBadInputsNameTheFile) {
  const fs::path dir = globe::testing::freshTempDir("bad-inputs");
  TilerOptions options;
  options.outputDir = dir / "pyramid";
  options.inputs = {(dir / "nope.DEM").string()};
  auto report = runTiler(options);
  ASSERT_FALSE(report);
  EXPECT_NE(report.error().find("nope.DEM"), std::string::npos) << report.error();
  EXPECT_FALSE(fs::exists(dir / "pyramid" / "manifest.json"));

  options.inputs = globe::testing::bundledInputs();
  options.verticesPerSide = 16;
  report = runTiler(options);
  ASSERT_FALSE(report);
  EXPECT_NE(report.error().find("2^k+1"), std::string::npos) << report.error();
}

TEST(TilerOptions, OtherBlockSizesAndLevelCaps) {
  const fs::path out = globe::testing::freshTempDir("n33") / "pyramid";
  TilerOptions options;
  options.inputs = globe::testing::bundledInputs();
  options.outputDir = out;
  options.verticesPerSide = 33;
  options.maxLevel = 9;
  auto report = runTiler(options);
  ASSERT_TRUE(report) << report.error();
  auto manifest = formats::readManifest(out);
  ASSERT_TRUE(manifest) << manifest.error();
  EXPECT_EQ(manifest->verticesPerSide, 33u);
  EXPECT_EQ(manifest->maxLevel(), 9u);
  EXPECT_EQ(manifest->levels[5].tileCount, 64u * 32u);  // ETOPO20 with N = 33 stops at level 5
}

}  // namespace
}  // namespace globe::tiling
