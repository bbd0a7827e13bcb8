// Sharded tiling (globe-tiler --shard K/N, then merge) ends byte-identical to one run: 1, 2, 4 and
// 7 shards over real data whose voids, coasts and source edges cross the shard borders; a shard
// killed and re-run; inputs read from nginx through GDAL's /vsicurl/; clear errors.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <set>
#include <thread>

#include "tests/support/build_paths.hpp"
#include "tests/support/command_run.hpp"
#include "tests/support/shared_commands.hpp"
#include "tests/support/nginx_server.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "tiling/shard_plan.hpp"
#include "tiling/source_set.hpp"
#include "tiling/tiling_plan.hpp"

namespace globe::tiling {
namespace {

namespace fs = std::filesystem;
using globe::testing::checksums;
using globe::testing::runCommand;

const std::string kTiler = GLOBE_TILER_EXE;
// Small packs so that the small real inputs make many units and every shard gets some.
const std::string kOptions = " -q --pack-tiles 8";

std::string dem(const std::string& name) {
  return std::string(GLOBE_SOURCE_DIR) + "/tests/data/dem/gtopo30/" + name;
}

// The world (20′, coasts and poles), a GTOPO30 coast with its ocean mask, Fuji (voids and the
// Suruga Bay coast) and two SRTM tiles side by side (a source boundary).
std::vector<std::string> shardInputs() {
  return {dem("ETOPO20.DEM"), dem("W002N52.DEM"), dem("E138N35_FUJI.DEM"), dem("N50E008.DEM"),
          dem("N50E009.DEM")};
}

std::string joined(const std::vector<std::string>& inputs) {
  std::string text;
  for (const std::string& input : inputs) text += " " + input;
  return text;
}

// Runs every shard of N, then the merge; fails the test on any error.
void tileInShards(const fs::path& out, uint32_t count, const std::string& inputs,
                  const std::string& extra = "") {
  for (uint32_t k = 0; k < count; ++k) {
    const auto run = runCommand(kTiler + kOptions + extra + " -j 1 --shard " + std::to_string(k) +
                                "/" + std::to_string(count) + " -o " + out.string() + inputs);
    ASSERT_EQ(run.exitCode, 0) << run.output;
  }
  const auto merged =
      runCommand(kTiler + " merge" + kOptions + extra + " -o " + out.string() + inputs);
  ASSERT_EQ(merged.exitCode, 0) << merged.output;
}

// Tiled once per CTest run (sharedCommands): every test here compares with it.
const fs::path& wholePyramid() {
  static const fs::path out = [] {
    const globe::testing::SharedRun run = globe::testing::sharedCommands(
        "shards-whole", {kTiler + kOptions + " -j 2 -o {dir}/pyramid" + joined(shardInputs())});
    EXPECT_EQ(run.exits.at(0).exitCode, 0) << run.exits.at(0).output;
    return run.dir / "pyramid";
  }();
  return out;
}

// How many shards of N hold units over the rectangle.
size_t shardsOver(const formats::BoundsDegrees& r, uint32_t count) {
  auto sources = openSources(shardInputs(), {});
  EXPECT_TRUE(static_cast<bool>(sources));
  const TilingPlan plan = planOfSources(*sources, 8);
  const ShardPartition partition =
      partitionShards(plan, defaultShardLevel(plan.maxLevel()), count, *sources, 8);
  std::set<uint32_t> shards;
  for (uint32_t k = 0; k < count; ++k) {
    for (const formats::PackId& unit : partition.units[k]) {
      const formats::BoundsDegrees b = packBoundsDegrees(unit, 8);
      if (b.west < r.east && r.west < b.east && b.south < r.north && r.south < b.north) {
        shards.insert(k);
      }
    }
  }
  return shards.size();
}

TEST(TilerShards, OneFourAndSevenShardsGiveTheOneMachinePyramid) {
  const auto reference = checksums(wholePyramid());
  ASSERT_GT(reference.size(), 100u);
  const std::string inputs = joined(shardInputs());
  for (uint32_t count : {1U, 4U, 7U}) {
    SCOPED_TRACE(std::to_string(count) + " shards");
    if (count >= 4) {
      // Shard borders cross Fuji's voids and coast, and the SRTM pair's shared edge at 9°E.
      EXPECT_GE(shardsOver({138.0, 35.0, 139.0, 36.0}, count), 2u);
      EXPECT_GE(shardsOver({8.9, 50.0, 9.1, 51.0}, count), 2u);
    }
    const fs::path out =
        globe::testing::freshTempDir("shards-" + std::to_string(count)) / "pyramid";
    tileInShards(out, count, inputs);
    EXPECT_EQ(checksums(out), reference);
    EXPECT_FALSE(fs::exists(out / "shards")) << "the merge removes what the shards left for it";
  }
}

// Small 3″ crops of the 20′ world (real relief, resampled by GDAL) where the geometry is hard: near
// Svalbard, where the apron of the coarsest tiles crosses the pole onto this meridian from the
// opposite one, and on both sides of the antimeridian over Fiji.
TEST(TilerShards, ShardsNearThePoleAndAcrossTheAntimeridianGiveTheOneMachinePyramid) {
  const fs::path root = globe::testing::freshTempDir("shards-polar");
  std::string inputs = " " + dem("ETOPO20.DEM");
  const std::vector<std::pair<std::string, std::string>> crops = {
      {"svalbard", "16.8 78.8 16.95 78.7"},
      {"fiji-east", "179.9 -16.75 180 -16.9"},
      {"fiji-west", "-180 -16.75 -179.9 -16.9"}};
  for (const auto& [name, window] : crops) {
    const fs::path crop = root / (name + ".tif");
    const auto made = runCommand("gdal_translate -q -of GTiff -ot Int16 -r bilinear -tr " +
                                 std::string("0.000833333333333 0.000833333333333 -projwin ") +
                                 window + " " + dem("ETOPO20.DEM") + " " + crop.string());
    ASSERT_EQ(made.exitCode, 0) << made.output;
    inputs += " " + crop.string();
  }
  const fs::path whole = root / "whole";
  const auto run = runCommand(kTiler + kOptions + " -o " + whole.string() + inputs);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto reference = checksums(whole);
  for (uint32_t count : {3U, 5U}) {
    const fs::path out = root / ("sharded-" + std::to_string(count));
    tileInShards(out, count, inputs);
    EXPECT_EQ(checksums(out), reference) << count << " shards";
  }
}

pid_t spawn(const std::vector<std::string>& arguments) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::vector<std::string> args = arguments;
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, STDOUT_FILENO);
    ::dup2(devnull, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

size_t countFiles(const fs::path& dir, const std::string& extension) {
  size_t count = 0;
  std::error_code error;
  for (auto it = fs::recursive_directory_iterator(dir, error);
       !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
    count += it->path().extension() == extension ? 1 : 0;
  }
  return count;
}

TEST(TilerShards, AKilledShardRerunAndTheMergeGiveTheOneMachinePyramid) {
  const auto reference = checksums(wholePyramid());
  const fs::path out = globe::testing::freshTempDir("shards-killed") / "pyramid";
  const std::vector<std::string> inputs = shardInputs();
  const auto first =
      runCommand(kTiler + kOptions + " -j 1 --shard 0/3 -o " + out.string() + joined(inputs));
  ASSERT_EQ(first.exitCode, 0) << first.output;
  std::vector<std::string> shard1 = {kTiler, "-q",      "--pack-tiles", "8",  "-j",
                                     "1",    "--shard", "1/3",          "-o", out.string()};
  shard1.insert(shard1.end(), inputs.begin(), inputs.end());
  // Killed a few milliseconds after its first packs are written, mid-run on any machine.
  const pid_t pid = spawn(shard1);
  int status = 0;
  bool exited = false;
  const size_t packsBefore = countFiles(out, ".pack");
  while (!(exited = ::waitpid(pid, &status, WNOHANG) == pid) &&
         countFiles(out, ".pack") < packsBefore + 3) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  if (!exited) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
  }
  EXPECT_TRUE(WIFSIGNALED(status)) << "the kill should land while the shard runs";
  EXPECT_FALSE(fs::exists(out / "shards" / "1-of-3.json")) << "a killed shard is not finished";

  // The merge refuses while a shard is unfinished, naming it.
  const auto early =
      runCommand(kTiler + " merge" + kOptions + " -o " + out.string() + joined(inputs));
  EXPECT_EQ(early.exitCode, 1);
  EXPECT_NE(early.output.find("shard 1/3 has not finished"), std::string::npos) << early.output;

  fs::create_directories(out / "L14");
  { std::ofstream(out / "L14" / "0_0.pack.tmp-99999-1") << "a killed shard's half-written pack"; }
  const auto rerun =
      runCommand(kTiler + kOptions + " -j 1 --shard 1/3 -o " + out.string() + joined(inputs));
  ASSERT_EQ(rerun.exitCode, 0) << rerun.output;
  EXPECT_NE(rerun.output.find("reused"), std::string::npos) << rerun.output;
  tileInShards(out, 3, joined(inputs));  // shard 1 again: idempotent, every pack reused
  EXPECT_EQ(checksums(out), reference);
  // A merge run again (a requeued job) finds its work done and changes nothing.
  const auto again =
      runCommand(kTiler + " merge" + kOptions + " -o " + out.string() + joined(inputs));
  EXPECT_EQ(again.exitCode, 0) << again.output;
  EXPECT_NE(again.output.find("already merged"), std::string::npos) << again.output;
  EXPECT_EQ(checksums(out), reference);
}

TEST(TilerShards, ShardsReadInputsFromNginxByVsicurl) {
  const fs::path root = globe::testing::freshTempDir("shards-http");
  // A Cloud-Optimized GeoTIFF of Fuji (voids, coast) beside the 20′ world, served by nginx.
  const fs::path cog = root / "www" / "fuji-cog.tif";
  fs::create_directories(cog.parent_path());
  const auto translated =
      runCommand("gdal_translate -q -of COG " + dem("E138N35_FUJI.DEM") + " " + cog.string());
  ASSERT_EQ(translated.exitCode, 0) << translated.output;
  globe::testing::NginxServer::Options serve;
  serve.root = root / "www";
  auto server = globe::testing::NginxServer::start(serve);
  ASSERT_TRUE(server && server->running());
  // For the globe-tiler runs only: GDAL in this process must still list folders (sidecars).
  struct ScopedEnvironment {
    ScopedEnvironment() {
      ::setenv("GDAL_DISABLE_READDIR_ON_OPEN", "EMPTY_DIR", 1);
      ::setenv("NO_PROXY", "127.0.0.1", 1);
    }
    ~ScopedEnvironment() {
      ::unsetenv("GDAL_DISABLE_READDIR_ON_OPEN");
      ::unsetenv("NO_PROXY");
    }
    ScopedEnvironment(const ScopedEnvironment&) = delete;
    ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;
  } environment;
  const std::string url = "/vsicurl/" + server->url("/fuji-cog.tif");
  const std::string httpInputs = " " + dem("ETOPO20.DEM") + " " + url;

  const fs::path local = root / "local";
  const auto whole = runCommand(kTiler + kOptions + " -o " + local.string() + " " +
                                dem("ETOPO20.DEM") + " " + cog.string());
  ASSERT_EQ(whole.exitCode, 0) << whole.output;
  const fs::path oneMachine = root / "one-machine";
  const auto wholeHttp = runCommand(kTiler + kOptions + " -o " + oneMachine.string() + httpInputs);
  ASSERT_EQ(wholeHttp.exitCode, 0) << wholeHttp.output;
  // The shards' list of inputs in a file, as for thousands of sources.
  const fs::path list = root / "inputs.txt";
  {
    std::ofstream(list) << "# the world, then Fuji from the server\n"
                        << dem("ETOPO20.DEM") << "\n\n"
                        << url << "\n";
  }
  const fs::path sharded = root / "sharded";
  tileInShards(sharded, 3, "", " --inputs " + list.string());
  EXPECT_EQ(checksums(sharded), checksums(oneMachine));

  // The packs are those of the local file (the manifest and plan name the URL instead).
  auto packsOf = [](const fs::path& dir) {
    auto sums = checksums(dir);
    std::erase_if(sums, [](const auto& file) { return !file.first.ends_with(".pack"); });
    return sums;
  };
  EXPECT_EQ(packsOf(sharded), packsOf(local));
  size_t ranged = 0;
  for (const std::string& line : server->accessLog()) {
    ranged += line.find("fuji-cog.tif 206") != std::string::npos ? 1 : 0;
  }
  EXPECT_GT(ranged, 0u) << "GDAL reads the COG by ranges (206 Partial Content)";
}

TEST(TilerShards, BadShardArgumentsAreRefusedClearly) {
  const fs::path out = globe::testing::freshTempDir("shards-bad") / "pyramid";
  const std::string inputs = " " + dem("W002N52.DEM");
  for (const std::string spec : {"3/3", "1", "a/2", "0/0", "-1/2"}) {
    const auto run = runCommand(kTiler + " -q --shard " + spec + " -o " + out.string() + inputs);
    EXPECT_EQ(run.exitCode, 2) << spec;
    EXPECT_NE(run.output.find("K/N"), std::string::npos) << run.output;
  }
  const auto missingList =
      runCommand(kTiler + " -q --inputs /nonexistent/list.txt -o " + out.string());
  EXPECT_EQ(missingList.exitCode, 2);
  EXPECT_NE(missingList.output.find("/nonexistent/list.txt"), std::string::npos);
  const auto noShards = runCommand(kTiler + " merge -q -o " + out.string() + inputs);
  EXPECT_EQ(noShards.exitCode, 1);
  EXPECT_NE(noShards.output.find("run the shards"), std::string::npos) << noShards.output;
  const auto level =
      runCommand(kTiler + " -q --shard 0/2 --shard-level 30 -o " + out.string() + inputs);
  EXPECT_EQ(level.exitCode, 1);
  EXPECT_NE(level.output.find("--shard-level 30"), std::string::npos) << level.output;
}

TEST(TilerShards, PlanPrintsEveryShardAndTheMerge) {
  const auto run = runCommand(kTiler + " plan --shards 4 --pack-tiles 8" + joined(shardInputs()));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  for (const std::string row : {"0/4", "1/4", "2/4", "3/4", "merge", "source MB", "expected"}) {
    EXPECT_NE(run.output.find(row), std::string::npos) << row << "\n" << run.output;
  }
}

TEST(ShardPlan, PartitionIsCompleteDisjointAndBalanced) {
  auto sources = openSources(shardInputs(), {});
  ASSERT_TRUE(static_cast<bool>(sources));
  const TilingPlan plan = planOfSources(*sources, 8);
  const uint32_t level = defaultShardLevel(plan.maxLevel());
  for (uint32_t count : {1U, 3U, 7U, 1000U}) {
    const ShardPartition partition = partitionShards(plan, level, count, *sources, 8);
    std::vector<formats::PackId> all;
    double heaviest = 0, total = 0;
    for (uint32_t k = 0; k < count; ++k) {
      all.insert(all.end(), partition.units[k].begin(), partition.units[k].end());
      heaviest = std::max(heaviest, partition.sourceSamples[k]);
      total += partition.sourceSamples[k];
    }
    std::sort(all.begin(), all.end());
    EXPECT_EQ(all, plan.packs(level)) << count << " shards: every unit once";
    // Contiguous runs cut where a unit's middle crosses k/N of the total.
    EXPECT_LE(heaviest, total / count + partition.heaviestUnitSamples + count) << count;
    if (count == 3) {
      EXPECT_LT(heaviest, 1.5 * total / count);
    }
  }
}

TEST(ShardPlan, PointsBelongToOnePackAcrossTheAntimeridianAndPoles) {
  // The east edge of the last column is its own (tiles are closed there); beyond it wraps.
  EXPECT_EQ(packHolding(180.0, 0.0, 3, 2).x, 7u);
  EXPECT_EQ(packHolding(-180.0, 0.0, 3, 2).x, 0u);
  EXPECT_EQ(packHolding(190.0, 10.0, 3, 2), packHolding(-170.0, 10.0, 3, 2));
  EXPECT_EQ(packHolding(0.0, 90.0, 3, 2).y, 0u);
  EXPECT_EQ(packHolding(0.0, -90.0, 3, 2).y, 3u);  // 8 tiles tall at level 3: 4 packs of 2
  // A point on a border belongs to the pack east / south of it.
  const double packDegrees = 180.0 / 8 * 2;
  EXPECT_EQ(packHolding(-180.0 + packDegrees, 0.0, 3, 2).x, 1u);
  EXPECT_EQ(packHolding(-180.0 + packDegrees - 1e-12, 0.0, 3, 2).x, 0u);
}

}  // namespace
}  // namespace globe::tiling
