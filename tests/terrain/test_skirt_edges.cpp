// Skirts only where a crack can open: neighbours across every edge, the antimeridian and the
// poles, and the index ranges that draw exactly the grid plus the chosen skirts.
#include <gtest/gtest.h>

#include <set>

#include "geo/tiling_scheme.hpp"
#include "terrain/skirt_edges.hpp"
#include "terrain/tile_mesh.hpp"

namespace globe::terrain {
namespace {

using geo::TileId;

constexpr SkirtEdgeMask bit(TileEdge edge) {
  return SkirtEdgeMask{1} << static_cast<uint32_t>(edge);
}

TEST(SkirtEdges, NeighboursWrapAtTheAntimeridianAndStopAtThePoles) {
  const uint32_t level = 3;
  const uint32_t columns = geo::GeographicTilingScheme::tilesX(level);
  const uint32_t rows = geo::GeographicTilingScheme::tilesY(level);
  EXPECT_EQ(sameLevelNeighbour({level, 0, 2}, TileEdge::West), (TileId{level, columns - 1, 2}));
  EXPECT_EQ(sameLevelNeighbour({level, columns - 1, 2}, TileEdge::East), (TileId{level, 0, 2}));
  EXPECT_EQ(sameLevelNeighbour({level, 5, 2}, TileEdge::North), (TileId{level, 5, 1}));
  EXPECT_EQ(sameLevelNeighbour({level, 5, 2}, TileEdge::South), (TileId{level, 5, 3}));
  EXPECT_FALSE(sameLevelNeighbour({level, 5, 0}, TileEdge::North).has_value());
  EXPECT_FALSE(sameLevelNeighbour({level, 5, rows - 1}, TileEdge::South).has_value());
  // Level 0 has two tiles side by side: each is the other's east and west neighbour.
  EXPECT_EQ(sameLevelNeighbour({0, 0, 0}, TileEdge::West), (TileId{0, 1, 0}));
  EXPECT_EQ(sameLevelNeighbour({0, 0, 0}, TileEdge::East), (TileId{0, 1, 0}));
  EXPECT_FALSE(sameLevelNeighbour({0, 0, 0}, TileEdge::North).has_value());
}

TEST(SkirtEdges, OnlyEdgesWithoutADrawnSameLevelNeighbourGetSkirts) {
  // A 3×3 block of level-5 tiles; the centre is surrounded, the corners have two neighbours.
  std::unordered_set<TileId> drawn;
  for (uint32_t y = 10; y < 13; ++y) {
    for (uint32_t x = 20; x < 23; ++x) drawn.insert({5, x, y});
  }
  EXPECT_EQ(neededSkirtEdges({5, 21, 11}, drawn), 0u);
  EXPECT_EQ(neededSkirtEdges({5, 20, 10}, drawn), bit(TileEdge::North) | bit(TileEdge::West));
  EXPECT_EQ(neededSkirtEdges({5, 22, 12}, drawn), bit(TileEdge::South) | bit(TileEdge::East));
  // A coarser tile next to the block and finer tiles inside a neighbour do not count as
  // same-level neighbours: the edge facing them keeps its skirt.
  drawn.insert({4, 11, 5});  // covers level-5 columns 22..23, rows 10..11 — not x=23
  drawn.erase({5, 22, 11});
  for (const TileId& child : TileId{5, 22, 11}.children()) drawn.insert(child);
  EXPECT_EQ(neededSkirtEdges({5, 21, 11}, drawn), bit(TileEdge::East));
  EXPECT_EQ(neededSkirtEdges({5, 21, 10}, drawn), bit(TileEdge::North));
}

TEST(SkirtEdges, CoarserNeighboursAreTheOnesWhoseAncestorIsDrawn) {
  // Level-6 tile (40, 20): west of it its neighbour's parent is drawn, north its neighbour's
  // grandparent, east its neighbour's children (finer), south nothing at all.
  const TileId tile{6, 40, 20};
  std::unordered_set<TileId> drawn{tile, TileId{6, 39, 20}.parent(),
                                   TileId{6, 40, 19}.parent().parent()};
  for (const TileId& child : TileId{6, 41, 20}.children()) drawn.insert(child);
  EXPECT_EQ(coarserNeighbourEdges(tile, drawn), bit(TileEdge::West) | bit(TileEdge::North));
  EXPECT_EQ(neededSkirtEdges(tile, drawn), bit(TileEdge::North) | bit(TileEdge::South) |
                                               bit(TileEdge::West) | bit(TileEdge::East));
  // A same-level neighbour drawn: not coarser. Beyond a pole: none.
  drawn.insert({6, 39, 20});
  EXPECT_EQ(coarserNeighbourEdges(tile, drawn), bit(TileEdge::North));
  EXPECT_EQ(coarserNeighbourEdges({6, 2, 0}, {TileId{5, 0, 0}}), bit(TileEdge::West));
  // Across the antimeridian.
  EXPECT_EQ(coarserNeighbourEdges({6, 0, 20}, {TileId{5, 63, 10}}), bit(TileEdge::West));
}

TEST(SkirtEdges, PolarRowAndAntimeridianTiles) {
  const uint32_t level = 2;
  const uint32_t columns = geo::GeographicTilingScheme::tilesX(level);
  std::unordered_set<TileId> drawn;
  for (uint32_t x = 0; x < columns; ++x) drawn.insert({level, x, 0});
  // The whole polar row: east/west neighbours all drawn (wrapping), north is the pole, south none.
  for (uint32_t x = 0; x < columns; ++x) {
    EXPECT_EQ(neededSkirtEdges({level, x, 0}, drawn), bit(TileEdge::North) | bit(TileEdge::South))
        << x;
  }
}

// The ranges cover exactly the grid triangles plus the chosen edges' skirt triangles, in the
// shared index buffer's layout, merging adjacent runs.
TEST(SkirtEdges, IndexRangesSelectTheGridAndTheChosenSkirts) {
  for (uint32_t n : {3u, 5u, 17u, 33u}) {
    const std::vector<uint32_t> indices = buildGridIndices(n, true);
    const uint32_t gridCount = (n - 1) * (n - 1) * 6;
    const uint32_t edgeCount = (n - 1) * 6;
    ASSERT_EQ(indices.size(), gridCount + 4 * edgeCount);
    for (SkirtEdgeMask mask = 0; mask <= kAllSkirtEdges; ++mask) {
      std::array<IndexRange, 3> ranges;
      const uint32_t used = skirtedIndexRanges(n, mask, ranges);
      ASSERT_GE(used, 1u);
      ASSERT_LE(used, 3u);
      std::set<uint32_t> covered;
      uint32_t total = 0;
      for (uint32_t r = 0; r < used; ++r) {
        ASSERT_LE(ranges[r].first + ranges[r].count, indices.size());
        if (r > 0) {  // adjacent runs are merged
          EXPECT_GT(ranges[r].first, ranges[r - 1].first + ranges[r - 1].count);
        }
        for (uint32_t i = ranges[r].first; i < ranges[r].first + ranges[r].count; ++i) {
          covered.insert(i);
        }
        total += ranges[r].count;
      }
      EXPECT_EQ(covered.size(), total);
      std::set<uint32_t> expected;
      for (uint32_t i = 0; i < gridCount; ++i) expected.insert(i);
      for (uint32_t edge = 0; edge < 4; ++edge) {
        if ((mask & (SkirtEdgeMask{1} << edge)) == 0) continue;
        for (uint32_t i = 0; i < edgeCount; ++i) expected.insert(gridCount + edge * edgeCount + i);
      }
      EXPECT_EQ(covered, expected) << "n " << n << " mask " << mask;
      // The skirt triangles of edge e use that edge's skirt vertices only.
      for (uint32_t edge = 0; edge < 4; ++edge) {
        const auto side = static_cast<TileEdge>(edge);
        for (uint32_t i = 0; i < edgeCount; ++i) {
          const uint32_t v = indices[gridCount + edge * edgeCount + i];
          if (v < n * n) continue;  // the edge's own grid vertices
          EXPECT_GE(v, skirtVertexIndex(side, 0, n));
          EXPECT_LE(v, skirtVertexIndex(side, n - 1, n));
        }
      }
    }
  }
}

}  // namespace
}  // namespace globe::terrain
