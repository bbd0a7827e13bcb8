// Tests for geo/tile_id.hpp: quadtree navigation, ordering and hashing.
#include "geo/tile_id.hpp"

#include <algorithm>
#include <unordered_set>
#include <vector>

#include <gtest/gtest.h>

namespace globe::geo {
namespace {

TEST(TileId, ParentOfLevelZeroIsItself) {
  EXPECT_EQ((TileId{0, 0, 0}).parent(), (TileId{0, 0, 0}));
  EXPECT_EQ((TileId{0, 1, 0}).parent(), (TileId{0, 1, 0}));
}

TEST(TileId, ChildrenAreNwNeSwSe) {
  const std::array<TileId, 4> children = TileId{3, 5, 6}.children();
  EXPECT_EQ(children[0], (TileId{4, 10, 12}));  // NW: west column, northern (smaller y) row
  EXPECT_EQ(children[1], (TileId{4, 11, 12}));  // NE
  EXPECT_EQ(children[2], (TileId{4, 10, 13}));  // SW
  EXPECT_EQ(children[3], (TileId{4, 11, 13}));  // SE
}

TEST(TileId, ParentChildRoundTrip) {
  for (uint32_t level = 0; level < kMaxLevel; ++level) {
    const uint32_t maxX = (uint32_t{2} << level) - 1;
    const uint32_t maxY = (uint32_t{1} << level) - 1;
    for (const TileId tile :
         {TileId{level, 0, 0}, TileId{level, maxX, maxY}, TileId{level, maxX / 3, maxY / 2}}) {
      for (const TileId& child : tile.children()) {
        EXPECT_EQ(child.level, level + 1);
        EXPECT_EQ(child.parent(), tile);
      }
    }
  }
}

TEST(TileId, OrderingIsLevelThenXThenY) {
  std::vector<TileId> tiles{{1, 0, 1}, {0, 1, 0}, {1, 1, 0}, {0, 0, 0}, {1, 0, 0}};
  std::sort(tiles.begin(), tiles.end());
  const std::vector<TileId> expected{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 0, 1}, {1, 1, 0}};
  EXPECT_EQ(tiles, expected);
}

TEST(TileId, HashHasNoCollisionsAndSpreadsLowBits) {
  constexpr size_t kBuckets = 1024;
  std::unordered_set<size_t> hashes;
  std::vector<int> bucketCounts(kBuckets, 0);
  size_t tileCount = 0;
  const std::hash<TileId> hasher;
  for (uint32_t level = 0; level <= 8; ++level) {
    for (uint32_t y = 0; y < (uint32_t{1} << level); ++y) {
      for (uint32_t x = 0; x < (uint32_t{2} << level); ++x) {
        const size_t h = hasher(TileId{level, x, y});
        hashes.insert(h);
        ++bucketCounts[h % kBuckets];
        ++tileCount;
      }
    }
  }
  EXPECT_EQ(tileCount, 174762u);
  EXPECT_EQ(hashes.size(), tileCount);  // no collisions at all
  // ~170 per bucket: a good mix stays well within +-40%.
  const double mean = static_cast<double>(tileCount) / kBuckets;
  const auto [lowest, highest] = std::minmax_element(bucketCounts.begin(), bucketCounts.end());
  EXPECT_GT(*lowest, 0.6 * mean);
  EXPECT_LT(*highest, 1.4 * mean);

  std::unordered_set<TileId> set{{0, 0, 0}, {1, 0, 0}, {0, 0, 0}};
  EXPECT_EQ(set.size(), 2u);
  EXPECT_NE(hasher(TileId{kMaxLevel, 0, 0}), hasher(TileId{kMaxLevel, 1, 0}));
}

}  // namespace
}  // namespace globe::geo
