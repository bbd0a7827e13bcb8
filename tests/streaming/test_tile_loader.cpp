// TileLoader on the bundled real pyramid: priorities, cancellation, the in-flight limit, the
// byte budget after each poll, failures reported once (inline runner, deterministic), and
// many concurrent loads equal to TileStore::loadBlock (thread pool).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <thread>
#include <vector>

#include "core/thread_pool_runner.hpp"
#include "geo/tiling_scheme.hpp"
#include "streaming/block_cache.hpp"
#include "streaming/tile_loader.hpp"
#include "streaming/tile_store.hpp"
#include "tests/streaming/loader_test_pyramid.hpp"
#include "tests/support/inline_runner.hpp"
#include "tests/support/test_io_util.hpp"

namespace globe::streaming {
namespace {

using geo::TileId;

std::unique_ptr<TileStore> openStore(const std::filesystem::path& dir) {
  auto store = TileStore::open(dir);
  EXPECT_TRUE(store) << store.error();
  return store ? std::move(*store) : nullptr;
}

// `count` level-14 tiles in a row eastwards from Mount Fuji: all present in the pyramid.
std::vector<TileId> fujiRow(uint32_t count, uint32_t rowOffset = 0) {
  const auto fuji = geo::GeographicTilingScheme::positionToTile(geo::degreesToRadians(138.73),
                                                                geo::degreesToRadians(35.36), 14);
  std::vector<TileId> tiles;
  for (uint32_t i = 0; i < count; ++i) tiles.push_back({14, fuji->x + i, fuji->y + rowOffset});
  return tiles;
}

std::vector<LoadRequest> withPriorities(const std::vector<TileId>& tiles,
                                        const std::vector<double>& priorities) {
  std::vector<LoadRequest> requests;
  for (size_t i = 0; i < tiles.size(); ++i) requests.push_back({tiles[i], priorities[i]});
  return requests;
}

std::vector<TileId> arrivedTiles(const PollResult& result) {
  std::vector<TileId> tiles;
  for (const auto& arrival : result.arrived) tiles.push_back(arrival.tile);
  return tiles;
}

// Every load the inline runner holds is run, then collected: one frame of a fast disk.
PollResult runAndPoll(globe::testing::InlineRunner& runner, BlockCache& cache, TileLoader& loader) {
  runner.runAll();
  cache.beginFrame();
  return loader.poll();
}

class TileLoaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    store_ = openStore(testing::loaderTestPyramid());
    ASSERT_NE(store_, nullptr);
  }
  std::unique_ptr<TileStore> store_;
  globe::testing::InlineRunner runner_;
  BlockCache cache_{64 << 20};
};

TEST_F(TileLoaderTest, LoadsTheHighestPriorityFirst) {
  TileLoader loader(*store_, runner_, cache_);
  loader.setMaxInFlight(2);
  const auto tiles = fujiRow(6);
  const auto requests = withPriorities(tiles, {3, 1, 5, 2, 6, 4});
  loader.request(requests);
  EXPECT_EQ(runner_.queued(), 2U);

  std::vector<TileId> order;
  for (int frame = 0; frame < 3; ++frame) {
    const PollResult result = runAndPoll(runner_, cache_, loader);
    EXPECT_EQ(result.arrived.size(), 2U);
    for (const TileId& tile : arrivedTiles(result)) order.push_back(tile);
  }
  EXPECT_EQ(order,
            (std::vector<TileId>{tiles[4], tiles[2], tiles[5], tiles[0], tiles[3], tiles[1]}));
  const LoaderCounters c = loader.counters();
  EXPECT_EQ(c.requested, 6U);
  EXPECT_EQ(c.started, 6U);
  EXPECT_EQ(c.completed, 6U);
  EXPECT_EQ(c.inFlight, 0U);
  EXPECT_EQ(c.pending, 0U);
  for (const TileId& tile : tiles) EXPECT_EQ(loader.state(tile), TileState::Resident);
}

TEST_F(TileLoaderTest, TiesKeepRequestOrderAndDuplicatesKeepTheirHigherPriority) {
  TileLoader loader(*store_, runner_, cache_);
  loader.setMaxInFlight(1);
  const auto t = fujiRow(3);
  const std::vector<LoadRequest> requests{{t[0], 1}, {t[1], 1}, {t[2], 0}, {t[2], 7}};
  loader.request(requests);
  std::vector<TileId> order;
  for (int frame = 0; frame < 3; ++frame) {
    for (const TileId& tile : arrivedTiles(runAndPoll(runner_, cache_, loader))) {
      order.push_back(tile);
    }
  }
  EXPECT_EQ(order, (std::vector<TileId>{t[2], t[0], t[1]}));
  EXPECT_EQ(loader.counters().requested, 3U);
}

// A source that reads tiles of the same pair (x / 2) in one request, as a remote pack reads
// adjacent blocks: the loader hands each pair to one task.
class PairedSource final : public TileSource<terrain::HeightBlock> {
 public:
  explicit PairedSource(TileStore& store) : store_(store) {}
  Result<std::optional<terrain::HeightBlock>> load(const TileId& tile) override {
    return store_.load(tile);
  }
  std::string location(const TileId& tile) const override { return store_.location(tile); }
  std::vector<TileId> readableWith(const TileId& first,
                                   std::span<const TileId> candidates) override {
    std::vector<TileId> together;
    for (const TileId& tile : candidates) {
      if (tile.y == first.y && tile.x / 2 == first.x / 2) together.push_back(tile);
    }
    together.push_back({first.level, first.x ^ 1U, first.y + 1});  // not offered: ignored
    return together;
  }
  std::vector<Result<std::optional<terrain::HeightBlock>>> loadTogether(
      std::span<const TileId> tiles) override {
    groups.emplace_back(tiles.begin(), tiles.end());
    return TileSource::loadTogether(tiles);
  }
  std::vector<std::vector<TileId>> groups;

 private:
  TileStore& store_;
};

TEST_F(TileLoaderTest, TilesReadTogetherShareOneTaskAndOneSlot) {
  PairedSource source(*store_);
  TileLoader loader(source, runner_, cache_);
  loader.setMaxInFlight(1);
  auto tiles = fujiRow(6);
  if (tiles[0].x % 2 == 1) tiles = fujiRow(7), tiles.erase(tiles.begin());  // pairs aligned
  // Priorities put each tile's partner far behind it: it is still read with it.
  loader.request(withPriorities(tiles, {6, 3, 5, 2, 4, 1}));
  EXPECT_EQ(runner_.queued(), 1U);
  EXPECT_EQ(loader.counters().tasksInFlight, 1U);
  EXPECT_EQ(loader.counters().inFlight, 2U);
  std::vector<std::vector<TileId>> arrivals;
  for (int frame = 0; frame < 3; ++frame) {
    arrivals.push_back(arrivedTiles(runAndPoll(runner_, cache_, loader)));
  }
  const std::vector<std::vector<TileId>> pairs = {
      {tiles[0], tiles[1]}, {tiles[2], tiles[3]}, {tiles[4], tiles[5]}};
  EXPECT_EQ(arrivals, pairs);
  EXPECT_EQ(source.groups, pairs);
  const LoaderCounters c = loader.counters();
  EXPECT_EQ(c.started, 6U);
  EXPECT_EQ(c.readTogether, 3U);
  EXPECT_EQ(c.completed, 6U);
  EXPECT_EQ(c.tasksInFlight, 0U);
  EXPECT_EQ(c.inFlight, 0U);
  for (const TileId& tile : tiles) EXPECT_EQ(loader.state(tile), TileState::Resident);
}

TEST_F(TileLoaderTest, NeverHasMoreThanMaxInFlightLoads) {
  TileLoader loader(*store_, runner_, cache_);
  EXPECT_EQ(loader.maxInFlight(), TileLoader::kDefaultMaxInFlight);
  loader.setMaxInFlight(3);
  const auto tiles = fujiRow(10);
  loader.request(withPriorities(tiles, std::vector<double>(10, 1.0)));
  EXPECT_EQ(runner_.queued(), 3U);
  EXPECT_EQ(loader.counters().inFlight, 3U);
  EXPECT_EQ(loader.counters().pending, 7U);

  // A finished load holds its slot until poll() collects it.
  ASSERT_TRUE(runner_.runOne());
  EXPECT_EQ(runner_.queued(), 2U);
  EXPECT_EQ(loader.counters().inFlight, 3U);
  cache_.beginFrame();
  EXPECT_EQ(loader.poll().arrived.size(), 1U);
  EXPECT_EQ(runner_.queued(), 3U);
  EXPECT_EQ(loader.counters().inFlight, 3U);

  loader.setMaxInFlight(5);  // raising it starts more at once
  EXPECT_EQ(runner_.queued(), 5U);
  loader.setMaxInFlight(0);  // clamped to 1; cancels nothing
  EXPECT_EQ(loader.maxInFlight(), 1U);
  EXPECT_EQ(loader.counters().inFlight, 5U);
  while (loader.counters().completed < tiles.size()) {
    runAndPoll(runner_, cache_, loader);
    EXPECT_LE(runner_.queued(), 1U);
  }
  EXPECT_EQ(loader.counters().started, 10U);
}

TEST_F(TileLoaderTest, ANewRequestCancelsQueuedTilesNoLongerWanted) {
  TileLoader loader(*store_, runner_, cache_);
  loader.setMaxInFlight(1);
  const auto t = fujiRow(5);
  loader.request(withPriorities({t[0], t[1], t[2], t[3]}, {9, 8, 7, 6}));
  EXPECT_EQ(loader.state(t[0]), TileState::Loading);
  EXPECT_EQ(loader.state(t[1]), TileState::Pending);

  // The camera moved: only t2 is still wanted, t4 is new. t1 and t3 are cancelled; t0, in
  // flight, completes and is cached but is not counted as wanted.
  loader.request(withPriorities({t[2], t[4]}, {1, 2}));
  LoaderCounters c = loader.counters();
  EXPECT_EQ(c.cancelled, 2U);
  EXPECT_EQ(c.requested, 5U);  // t0..t3, then t4 (t2 was already queued)
  EXPECT_EQ(c.pending, 2U);
  EXPECT_EQ(loader.state(t[1]), TileState::NotRequested);
  EXPECT_EQ(loader.state(t[3]), TileState::NotRequested);

  EXPECT_EQ(arrivedTiles(runAndPoll(runner_, cache_, loader)), std::vector<TileId>{t[0]});
  EXPECT_EQ(arrivedTiles(runAndPoll(runner_, cache_, loader)), std::vector<TileId>{t[4]});
  EXPECT_EQ(arrivedTiles(runAndPoll(runner_, cache_, loader)), std::vector<TileId>{t[2]});
  c = loader.counters();
  EXPECT_EQ(c.started, 3U);
  EXPECT_EQ(c.completed, 3U);
  EXPECT_FALSE(loader.isResident(t[1]));

  // Resident tiles are not queued again; an empty request cancels nothing more.
  loader.request(withPriorities({t[0], t[2]}, {1, 1}));
  loader.request({});
  EXPECT_EQ(runner_.queued(), 0U);
  EXPECT_EQ(loader.counters().requested, 5U);
  EXPECT_EQ(loader.counters().cancelled, 2U);
}

TEST_F(TileLoaderTest, DeliversTheStoresBlocksAndCountsCacheUse) {
  TileLoader loader(*store_, runner_, cache_);
  const auto tiles = fujiRow(4, 2);
  loader.request(withPriorities(tiles, {1, 1, 1, 1}));
  EXPECT_FALSE(loader.isResident(tiles[0]));
  const PollResult result = runAndPoll(runner_, cache_, loader);
  ASSERT_EQ(result.arrived.size(), 4U);
  for (const auto& arrival : result.arrived) {
    EXPECT_GE(arrival.workerLatencySeconds, 0.0);
    EXPECT_GE(arrival.visibleLatencySeconds, arrival.workerLatencySeconds);
  }
  auto reference = openStore(testing::loaderTestPyramid());
  for (const TileId& tile : tiles) {
    const auto block = loader.get(tile);
    ASSERT_NE(block, nullptr);
    auto expected = reference->loadBlock(tile);
    ASSERT_TRUE(expected) << expected.error();
    EXPECT_EQ(block->verticesPerSide, expected->verticesPerSide);
    EXPECT_EQ(block->heights, expected->heights);
    EXPECT_TRUE(cache_.isPinned(tile));  // arrived this frame
  }
  EXPECT_EQ(loader.get(fujiRow(1, 40)[0]), nullptr);
  EXPECT_EQ(cache_.counters().hits, 4U);
  EXPECT_EQ(cache_.counters().misses, 1U);
  EXPECT_EQ(cache_.counters().loads, 4U);
}

TEST_F(TileLoaderTest, ATileBeyondThePyramidIsAbsentNotAnErrorAndNotRetried) {
  TileLoader loader(*store_, runner_, cache_);
  // Level 14 over the Pacific: the level exists, but only over Japan.
  const auto pacific = geo::GeographicTilingScheme::positionToTile(geo::degreesToRadians(-150.0),
                                                                   geo::degreesToRadians(0.0), 14);
  ASSERT_TRUE(pacific);
  const std::vector<LoadRequest> requests{{*pacific, 1}, {{20, 0, 0}, 1}};
  loader.request(requests);
  const PollResult result = runAndPoll(runner_, cache_, loader);
  EXPECT_TRUE(result.arrived.empty());
  EXPECT_TRUE(result.errors.empty());
  EXPECT_EQ(loader.state(*pacific), TileState::Absent);
  EXPECT_EQ(loader.counters().absent, 2U);
  loader.request(requests);
  EXPECT_EQ(runner_.queued(), 0U);
  EXPECT_EQ(loader.counters().started, 2U);
}

TEST_F(TileLoaderTest, ResidentBytesStayWithinTheBudgetAfterEveryPollExceptPinnedTiles) {
  const auto tiles = fujiRow(24, 5);
  const size_t block = 21 * 21 * 2 + BlockCache::kEntryOverheadBytes;  // 17² samples and apron
  BlockCache cache(6 * block);
  TileLoader loader(*store_, runner_, cache);
  // Each frame draws the four resident tiles it last received and wants the next eight.
  std::vector<TileId> drawn;
  for (size_t frame = 0; frame < 6; ++frame) {
    cache.beginFrame();
    EXPECT_EQ(cache.touch(drawn), drawn.size());  // last frame's arrivals are all still there
    std::vector<LoadRequest> wanted;
    for (size_t k = 0; k < 8 && frame * 4 + k < tiles.size(); ++k) {
      wanted.push_back({tiles[frame * 4 + k], -static_cast<double>(k)});
    }
    loader.request(wanted);
    runner_.runAll();
    const PollResult result = loader.poll();
    EXPECT_EQ(result.arrived.size(), 4U) << "frame " << frame;
    const BlockCacheCounters& c = cache.counters();
    EXPECT_LE(c.residentBytes, std::max(cache.budgetBytes(), c.pinnedBytes)) << "frame " << frame;
    for (const TileId& tile : drawn) EXPECT_TRUE(cache.contains(tile)) << "drawn, so pinned";
    drawn = arrivedTiles(result);
    for (const TileId& tile : drawn) EXPECT_TRUE(cache.contains(tile)) << "arrived, so pinned";
  }
  EXPECT_GT(cache.counters().evictions, 0U);
  EXPECT_LE(cache.counters().peakResidentBytes,
            std::max(cache.budgetBytes(), cache.counters().peakPinnedBytes));

  // When the frame's drawn tiles alone exceed the budget, the budget gives way to them only.
  cache.beginFrame();
  EXPECT_EQ(cache.touch(drawn), 4U);
  cache.setBudgetBytes(2 * block);
  EXPECT_EQ(cache.counters().residentBytes, 4 * block);
  EXPECT_EQ(cache.counters().pinnedBytes, 4 * block);
  // Next frame nothing is drawn: the next arrival brings the cache back within budget.
  loader.request(withPriorities({tiles[0]}, {1}));
  EXPECT_EQ(arrivedTiles(runAndPoll(runner_, cache, loader)), std::vector<TileId>{tiles[0]});
  EXPECT_EQ(cache.counters().residentBytes, 2 * block);
  EXPECT_TRUE(cache.contains(tiles[0]));
}

// A copy of the pyramid in which one pack is truncated and another is missing.
class DamagedPyramidTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::copy(testing::loaderTestPyramid(), dir_.path() / "pyramid",
                          std::filesystem::copy_options::recursive);
    store_ = openStore(dir_.path() / "pyramid");
    ASSERT_NE(store_, nullptr);
  }
  std::filesystem::path packFile(const TileId& tile) const {
    return formats::packPath(store_->location(),
                             formats::packOf(tile, store_->manifest().packTilesPerSide));
  }
  globe::testing::TempDir dir_;
  std::unique_ptr<TileStore> store_;
  globe::testing::InlineRunner runner_;
  BlockCache cache_{64 << 20};
};

TEST_F(DamagedPyramidTest, FailuresAreReportedOnceWithFileAndTileAndNotRetried) {
  const auto tiles = fujiRow(2);
  const TileId level13 = tiles[0].parent();
  ASSERT_NE(packFile(tiles[0]), packFile(level13));
  std::filesystem::resize_file(packFile(tiles[0]), 5000);  // truncated: both its tiles fail
  std::filesystem::remove(packFile(level13));              // missing

  TileLoader loader(*store_, runner_, cache_);
  const auto requests = withPriorities({tiles[0], tiles[1], level13}, {3, 2, 1});
  loader.request(requests);
  const PollResult result = runAndPoll(runner_, cache_, loader);
  EXPECT_TRUE(result.arrived.empty());
  ASSERT_EQ(result.errors.size(), 3U);
  EXPECT_EQ(result.errors[0].tile, tiles[0]);
  EXPECT_EQ(result.errors[0].file, packFile(tiles[0]));
  EXPECT_NE(result.errors[0].message.find(packFile(tiles[0]).string()), std::string::npos);
  EXPECT_NE(result.errors[0].message.find("truncated"), std::string::npos)
      << result.errors[0].message;
  EXPECT_NE(result.errors[0].message.find("tile 14/"), std::string::npos);
  EXPECT_EQ(result.errors[2].tile, level13);
  EXPECT_NE(result.errors[2].message.find("cannot open"), std::string::npos)
      << result.errors[2].message;
  EXPECT_EQ(loader.state(tiles[0]), TileState::Failed);

  // Wanted again frame after frame: neither reloaded nor reported again.
  for (int frame = 0; frame < 5; ++frame) {
    loader.request(requests);
    EXPECT_EQ(runner_.queued(), 0U);
    EXPECT_TRUE(runAndPoll(runner_, cache_, loader).errors.empty());
  }
  EXPECT_EQ(loader.counters().started, 3U);
  EXPECT_EQ(loader.counters().failed, 3U);
  EXPECT_EQ(loader.errors().size(), 3U);

  loader.forgetFailures();  // the caller may ask for a retry explicitly
  loader.request(requests);
  EXPECT_EQ(runAndPoll(runner_, cache_, loader).errors.size(), 3U);
  EXPECT_EQ(loader.errors().size(), 6U);
}

TEST_F(DamagedPyramidTest, APackTruncatedAfterItWasOpenedFailsTheReadOnly) {
  const auto tiles = fujiRow(2);
  TileLoader loader(*store_, runner_, cache_);
  loader.request(withPriorities({tiles[0]}, {1}));
  ASSERT_EQ(runAndPoll(runner_, cache_, loader).arrived.size(), 1U);  // the pack is open now

  const formats::PackLayout layout = store_->manifest().packLayout();
  std::filesystem::resize_file(packFile(tiles[1]), layout.indexEndOffset());
  loader.request(withPriorities({tiles[1]}, {1}));
  const PollResult result = runAndPoll(runner_, cache_, loader);
  ASSERT_EQ(result.errors.size(), 1U);
  EXPECT_EQ(result.errors[0].file, packFile(tiles[1]));
  EXPECT_NE(result.errors[0].message.find("unexpected end of file"), std::string::npos)
      << result.errors[0].message;
  EXPECT_TRUE(loader.isResident(tiles[0]));  // what was loaded stays usable
}

TEST_F(TileLoaderTest, TasksLeftInTheRunnerAfterTheLoaderIsGoneDoNothing) {
  {
    TileLoader loader(*store_, runner_, cache_);
    loader.request(withPriorities(fujiRow(3), {1, 1, 1}));
    EXPECT_EQ(runner_.queued(), 3U);
  }
  const uint64_t reads = store_->blockReads();
  EXPECT_EQ(runner_.runAll(), 3U);
  EXPECT_EQ(store_->blockReads(), reads);
  EXPECT_EQ(cache_.counters().loads, 0U);
}

// Polls until `done` holds, at most `timeout`: a thread pool has no other finish line.
template <class Done>
void pollUntil(TileLoader& loader, BlockCache& cache, Done done, std::vector<TileId>& arrived) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!done()) {
    ASSERT_TRUE(std::chrono::steady_clock::now() < deadline)
        << "loads did not finish within 60 s: " << loader.counters().completed << " completed, "
        << loader.counters().inFlight << " in flight, " << loader.counters().pending << " pending";
    cache.beginFrame();
    for (const TileId& tile : arrivedTiles(loader.poll())) arrived.push_back(tile);
    std::this_thread::yield();
  }
}

TEST_F(TileLoaderTest, AThreadPoolLoadsManyTilesExactlyAsTheStoreDoes) {
  core::ThreadPoolRunner pool(2);
  // Every tile of levels 11 and 12 over Japan and England: 1396 tiles in four packs.
  std::vector<LoadRequest> requests;
  for (uint32_t level : {11U, 12U}) {
    for (const formats::PackId& pack : store_->manifest().levels[level].packs) {
      const uint32_t side = store_->manifest().packTilesPerSide;
      for (size_t slot = 0; slot < size_t{side} * side; ++slot) {
        const TileId tile = formats::tileOfSlot(pack, slot, side);
        auto entry = store_->entry(tile);
        ASSERT_TRUE(entry) << entry.error();
        if (*entry) requests.push_back({tile, static_cast<double>(slot % 7)});
      }
    }
  }
  ASSERT_EQ(requests.size(), 820U + 576U);

  std::vector<TileId> arrived;
  {
    TileLoader loader(*store_, pool, cache_);
    loader.setMaxInFlight(8);
    loader.request(requests);
    pollUntil(
        loader, cache_, [&] { return loader.counters().completed == requests.size(); }, arrived);
    const LoaderCounters c = loader.counters();
    EXPECT_EQ(c.started, requests.size());
    EXPECT_EQ(c.failed + c.absent + c.cancelled + c.inFlight + c.pending, 0U);
  }
  ASSERT_EQ(arrived.size(), requests.size());
  EXPECT_EQ(std::set<TileId>(arrived.begin(), arrived.end()).size(), requests.size());

  auto reference = openStore(testing::loaderTestPyramid());
  for (const LoadRequest& r : requests) {
    const auto block = cache_.get(r.tile);
    ASSERT_NE(block, nullptr);
    auto expected = reference->loadBlock(r.tile);
    ASSERT_TRUE(expected) << expected.error();
    ASSERT_EQ(block->heights, expected->heights) << r.tile.level << "/" << r.tile.x;
  }
}

TEST_F(TileLoaderTest, AThreadPoolSurvivesAWantedSetThatKeepsChanging) {
  core::ThreadPoolRunner pool(2);
  BlockCache cache(200 * (17 * 17 * 2 + BlockCache::kEntryOverheadBytes));
  TileLoader loader(*store_, pool, cache);
  // A window of 30 tiles slides westwards along a row, one tile per frame, while loads run.
  auto row = fujiRow(60, 10);
  for (TileId& tile : row) tile.x -= 60;  // eastwards the fine data ends 27 tiles from Fuji
  std::vector<TileId> arrived;
  for (size_t frame = 0; frame + 30 <= row.size(); ++frame) {
    cache.beginFrame();
    std::vector<LoadRequest> wanted;
    for (size_t k = 0; k < 30; ++k) wanted.push_back({row[frame + k], -static_cast<double>(k)});
    loader.request(wanted);
    for (const TileId& tile : arrivedTiles(loader.poll())) arrived.push_back(tile);
    EXPECT_LE(loader.counters().inFlight, loader.maxInFlight());
  }
  // The last window must arrive in full.
  const std::vector<TileId> last(row.end() - 30, row.end());
  pollUntil(
      loader, cache,
      [&] {
        return loader.counters().inFlight + loader.counters().pending == 0 &&
               std::all_of(last.begin(), last.end(),
                           [&](const TileId& t) { return loader.isResident(t); });
      },
      arrived);
  const LoaderCounters c = loader.counters();
  EXPECT_EQ(c.absent + c.failed, 0U);
  EXPECT_EQ(c.started, c.completed);
  EXPECT_EQ(c.completed, arrived.size());
  EXPECT_EQ(c.requested, c.started + c.cancelled);
}

}  // namespace
}  // namespace globe::streaming
