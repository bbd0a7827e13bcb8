// BlockCache: LRU order, the byte budget and its one exception (the frame's pinned tiles),
// counters, on blocks of the bundled real pyramid.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "geo/tiling_scheme.hpp"
#include "streaming/block_cache.hpp"
#include "streaming/tile_store.hpp"
#include "tests/streaming/loader_test_pyramid.hpp"

namespace globe::streaming {
namespace {

using geo::TileId;
using Block = std::shared_ptr<const terrain::HeightBlock>;

// Real blocks: the level-14 tiles of a row over Mount Fuji, loaded once for the suite.
class BlockCacheTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    auto store = TileStore::open(testing::loaderTestPyramid());
    ASSERT_TRUE(store) << store.error();
    const auto fuji = geo::GeographicTilingScheme::positionToTile(geo::degreesToRadians(138.73),
                                                                  geo::degreesToRadians(35.36), 14);
    ASSERT_TRUE(fuji);
    for (uint32_t i = 0; i < 12; ++i) {
      const TileId tile{14, fuji->x + i, fuji->y};
      auto block = (*store)->loadBlock(tile);
      ASSERT_TRUE(block) << block.error();
      tiles_.push_back(tile);
      blocks_.push_back(std::make_shared<const terrain::HeightBlock>(std::move(*block)));
    }
  }
  static size_t blockBytes() { return BlockCache::entryBytes(*blocks_[0]); }
  static void insert(BlockCache& cache, size_t i) { cache.insert(tiles_[i], blocks_[i]); }
  static std::vector<TileId> tiles(std::initializer_list<size_t> indices) {
    std::vector<TileId> out;
    for (size_t i : indices) out.push_back(tiles_[i]);
    return out;
  }
  // The rule of block_cache.hpp, checked after every insert and budget change.
  static void expectWithinRule(const BlockCache& cache) {
    const BlockCacheCounters& c = cache.counters();
    EXPECT_LE(c.residentBytes, std::max(cache.budgetBytes(), c.pinnedBytes));
    EXPECT_LE(c.peakResidentBytes, std::max(cache.budgetBytes(), c.peakPinnedBytes));
  }

  static inline std::vector<TileId> tiles_;
  static inline std::vector<Block> blocks_;
};

TEST_F(BlockCacheTest, EntryBytesAreTheSamplesPlusADocumentedOverhead) {
  ASSERT_EQ(blocks_[0]->heights.size(), 17U * 17U);
  ASSERT_EQ(blocks_[0]->apron.size(), 21U * 21U - 17U * 17U);  // 2 vertices around (version 3)
  EXPECT_EQ(blockBytes(), 21U * 21U * 2U + BlockCache::kEntryOverheadBytes);
  BlockCache cache(1 << 20);
  insert(cache, 0);
  insert(cache, 1);
  EXPECT_EQ(cache.counters().residentBytes, 2 * blockBytes());
  EXPECT_EQ(cache.counters().entries, 2U);
}

TEST_F(BlockCacheTest, EvictsTheLeastRecentlyUsedFirst) {
  BlockCache cache(3 * blockBytes());
  for (size_t i = 0; i < 3; ++i) {
    cache.beginFrame();
    insert(cache, i);
  }
  EXPECT_EQ(cache.tilesByRecency(), tiles({2, 1, 0}));
  cache.beginFrame();
  insert(cache, 3);  // 0 is the least recent
  EXPECT_EQ(cache.tilesByRecency(), tiles({3, 2, 1}));
  EXPECT_FALSE(cache.contains(tiles_[0]));

  cache.beginFrame();
  EXPECT_EQ(cache.get(tiles_[1]), blocks_[1]);  // a use makes 1 the most recent
  insert(cache, 4);                             // so 2 goes
  EXPECT_EQ(cache.tilesByRecency(), tiles({4, 1, 3}));

  cache.beginFrame();
  EXPECT_EQ(cache.touch(tiles({3})), 1U);
  EXPECT_TRUE(cache.contains(tiles_[1]));  // contains() neither counts nor reorders
  insert(cache, 5);                        // so 1 goes
  EXPECT_EQ(cache.tilesByRecency(), tiles({5, 3, 4}));
  EXPECT_EQ(cache.counters().evictions, 3U);
  expectWithinRule(cache);
}

TEST_F(BlockCacheTest, TilesPinnedInTheFrameAreNeverEvictedAndOnlyTheyExceedTheBudget) {
  BlockCache cache(2 * blockBytes());
  insert(cache, 0);
  insert(cache, 1);
  cache.beginFrame();
  EXPECT_EQ(cache.touch(tiles({0, 1, 7})), 2U);  // 7 is not resident: ignored
  EXPECT_TRUE(cache.isPinned(tiles_[0]));
  EXPECT_FALSE(cache.isPinned(tiles_[7]));

  // Everything resident is pinned: the new block stays too (it was inserted in this frame),
  // the budget is exceeded by pinned bytes only.
  insert(cache, 2);
  EXPECT_EQ(cache.counters().entries, 3U);
  EXPECT_EQ(cache.counters().evictions, 0U);
  EXPECT_EQ(cache.counters().residentBytes, 3 * blockBytes());
  EXPECT_EQ(cache.counters().pinnedBytes, 3 * blockBytes());
  expectWithinRule(cache);

  // Next frame only 2 is drawn: the next insert evicts the unpinned 0 and 1 (least recent
  // first) and is back within budget.
  cache.beginFrame();
  EXPECT_EQ(cache.counters().pinnedBytes, 0U);
  EXPECT_EQ(cache.counters().entries, 3U);  // beginFrame itself evicts nothing
  cache.touch(tiles({2}));
  insert(cache, 3);
  EXPECT_EQ(cache.tilesByRecency(), tiles({3, 2}));
  EXPECT_EQ(cache.counters().evictions, 2U);
  EXPECT_EQ(cache.counters().residentBytes, 2 * blockBytes());
  EXPECT_EQ(cache.counters().peakResidentBytes, 3 * blockBytes());
  EXPECT_EQ(cache.counters().peakPinnedBytes, 3 * blockBytes());
  expectWithinRule(cache);
}

TEST_F(BlockCacheTest, ThePinnedTileSurvivesEvenWhenLeastRecent) {
  BlockCache cache(3 * blockBytes());
  for (size_t i = 0; i < 3; ++i) insert(cache, i);
  cache.beginFrame();
  cache.touch(tiles({0}));
  EXPECT_EQ(cache.get(tiles_[1]), blocks_[1]);
  EXPECT_EQ(cache.get(tiles_[2]), blocks_[2]);  // 0 is now the least recent, but pinned
  insert(cache, 3);
  insert(cache, 4);
  EXPECT_EQ(cache.tilesByRecency(), tiles({4, 3, 0}));
  expectWithinRule(cache);
}

TEST_F(BlockCacheTest, ALongSequenceNeverBreaksTheBudgetRule) {
  BlockCache cache(4 * blockBytes());
  // Each frame draws a sliding window of three tiles and receives two new ones.
  for (size_t frame = 0; frame < 40; ++frame) {
    cache.beginFrame();
    std::vector<TileId> drawn;
    for (size_t k = 0; k < 3; ++k) drawn.push_back(tiles_[(frame + k) % tiles_.size()]);
    std::vector<TileId> pinned;
    for (const TileId& tile : drawn) {
      if (cache.contains(tile)) pinned.push_back(tile);
    }
    EXPECT_EQ(cache.touch(drawn), pinned.size());
    insert(cache, (frame * 5) % tiles_.size());
    expectWithinRule(cache);
    insert(cache, (frame * 7 + 3) % tiles_.size());
    expectWithinRule(cache);
    for (const TileId& tile : pinned) EXPECT_TRUE(cache.contains(tile)) << "frame " << frame;
  }
  EXPECT_GT(cache.counters().evictions, 0U);
}

TEST_F(BlockCacheTest, LoweringTheBudgetEvictsAtOnceExceptPinned) {
  BlockCache cache(10 * blockBytes());
  for (size_t i = 0; i < 6; ++i) insert(cache, i);
  cache.beginFrame();
  cache.touch(tiles({0}));
  cache.setBudgetBytes(2 * blockBytes());
  EXPECT_EQ(cache.tilesByRecency(), tiles({0, 5}));
  cache.setBudgetBytes(0);
  EXPECT_EQ(cache.tilesByRecency(), tiles({0}));
  expectWithinRule(cache);
  EXPECT_EQ(cache.counters().evictions, 5U);
}

TEST_F(BlockCacheTest, CountsHitsMissesLoadsAndReplacements) {
  BlockCache cache(10 * blockBytes());
  insert(cache, 0);
  insert(cache, 1);
  EXPECT_EQ(cache.get(tiles_[0]), blocks_[0]);
  EXPECT_EQ(cache.get(tiles_[2]), nullptr);
  EXPECT_EQ(cache.get(tiles_[2]), nullptr);
  cache.insert(tiles_[0], blocks_[3]);  // replaces: same entry, new block
  cache.insert(tiles_[4], nullptr);     // ignored
  EXPECT_EQ(cache.get(tiles_[0]), blocks_[3]);
  const BlockCacheCounters& c = cache.counters();
  EXPECT_EQ(c.hits, 2U);
  EXPECT_EQ(c.misses, 2U);
  EXPECT_EQ(c.loads, 3U);
  EXPECT_EQ(c.entries, 2U);
  EXPECT_EQ(c.residentBytes, 2 * blockBytes());
  EXPECT_EQ(c.pinnedBytes, 2 * blockBytes());  // all inserted in this (the first) frame
}

TEST_F(BlockCacheTest, AnEvictedBlockStaysValidForWhoeverHoldsIt) {
  BlockCache cache(blockBytes());
  insert(cache, 0);
  const Block held = cache.get(tiles_[0]);
  cache.beginFrame();
  insert(cache, 1);
  EXPECT_FALSE(cache.contains(tiles_[0]));
  ASSERT_NE(held, nullptr);
  EXPECT_EQ(held->heights, blocks_[0]->heights);
  EXPECT_EQ(cache.counters().residentBytes, blockBytes());
}

}  // namespace
}  // namespace globe::streaming
