// sharedFixture: one build per key however many ask at once, nothing left by a failed build, and
// the shared bundled pyramid byte-identical to one this process tiles itself.
#include "tests/support/shared_fixture.hpp"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <thread>
#include <vector>

#include "tests/support/tiler_test_fixture.hpp"

namespace globe::testing {
namespace {

namespace fs = std::filesystem;

// Points GLOBE_TEST_FIXTURES at a private folder while it lives (the run's own is left alone).
class PrivateFixtureRoot {
 public:
  PrivateFixtureRoot() : root_(freshTempDir("shared-fixture-root")) {
    const char* saved = std::getenv("GLOBE_TEST_FIXTURES");
    if (saved != nullptr) saved_ = saved;
    ::setenv("GLOBE_TEST_FIXTURES", root_.c_str(), 1);
  }
  ~PrivateFixtureRoot() {
    if (saved_.empty()) {
      ::unsetenv("GLOBE_TEST_FIXTURES");
    } else {
      ::setenv("GLOBE_TEST_FIXTURES", saved_.c_str(), 1);
    }
  }
  const fs::path& root() const { return root_; }

 private:
  fs::path root_;
  std::string saved_;
};

bool writeFile(const fs::path& dir, const std::string& text) {
  fs::create_directories(dir);
  std::ofstream(dir / "file.txt") << text;
  return true;
}

std::string readFile(const fs::path& dir) {
  std::ifstream in(dir / "file.txt");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(SharedFixture, ManyAskingAtOnceGetOneBuild) {
  const PrivateFixtureRoot root;
  std::atomic<int> builds = 0;
  std::vector<fs::path> paths(8);
  std::vector<std::thread> threads;
  for (size_t i = 0; i < paths.size(); ++i) {
    threads.emplace_back([&, i] {
      paths[i] = sharedFixture("one key / with odd characters", [&](const fs::path& dir) {
        ++builds;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the others must wait
        return writeFile(dir, "built once");
      });
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(builds.load(), 1);
  for (const fs::path& path : paths) {
    EXPECT_EQ(path, paths.front());
    EXPECT_EQ(readFile(path), "built once");
  }
  EXPECT_EQ(paths.front().parent_path(), root.root());
  EXPECT_EQ(std::distance(fs::directory_iterator(paths.front()), fs::directory_iterator()), 1)
      << "nothing but what the build wrote lies in the fixture";
}

TEST(SharedFixture, OtherKeysGetOtherFolders) {
  const PrivateFixtureRoot root;
  const fs::path a = sharedFixture("a", [](const fs::path& dir) { return writeFile(dir, "a"); });
  const fs::path b = sharedFixture("b", [](const fs::path& dir) { return writeFile(dir, "b"); });
  EXPECT_NE(a, b);
  EXPECT_EQ(readFile(a), "a");
  EXPECT_EQ(readFile(b), "b");
}

TEST(SharedFixture, AFailedBuildLeavesNothingAndTheNextAskerBuildsAgain) {
  const PrivateFixtureRoot root;
  fs::path failed;
  EXPECT_NONFATAL_FAILURE(failed = sharedFixture("flaky",
                                                 [](const fs::path& dir) {
                                                   writeFile(dir, "half");
                                                   return false;
                                                 }),
                          "could not make the test fixture flaky");
  EXPECT_FALSE(fs::exists(failed));
  const fs::path built =
      sharedFixture("flaky", [](const fs::path& dir) { return writeFile(dir, "whole"); });
  EXPECT_EQ(built, failed);
  EXPECT_EQ(readFile(built), "whole");
}

TEST(SharedFixture, WithoutTheVariableEachProcessBuildsItsOwn) {
  const PrivateFixtureRoot root;
  ::unsetenv("GLOBE_TEST_FIXTURES");
  int builds = 0;
  const auto build = [&](const fs::path& dir) { return ++builds, writeFile(dir, "own"); };
  const fs::path first = sharedFixture("own", build);
  const fs::path second = sharedFixture("own", build);
  EXPECT_EQ(builds, 2);
  EXPECT_NE(first.parent_path().parent_path(), root.root());
  EXPECT_EQ(readFile(second), "own");
}

TEST(SharedFixture, TheSharedBundledPyramidIsTheOneThisProcessTiles) {
  // Under CTest bundledPyramid() is the run's shared copy, tiled by whichever test came first.
  const auto own = tilePyramid("own-bundled", bundledInputs());
  const auto shared = checksums(bundledPyramid());
  EXPECT_FALSE(shared.empty());
  EXPECT_EQ(shared, checksums(own));
}

}  // namespace
}  // namespace globe::testing
