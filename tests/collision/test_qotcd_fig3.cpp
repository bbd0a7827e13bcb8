// The paper's Fig. 3 on a 17x17 block: every vertex, every row and column segment and every
// quad of a synthetic tile, with distinct heights, a spike and no-data, checked exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "collision/grid_location.hpp"
#include "collision/qotcd.hpp"
#include "collision/qotcd_height.hpp"
#include "geo/tiling_scheme.hpp"
#include "tests/collision/collision_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::collision {
namespace {

using geo::TileId;
using globe::test::kN;
using testing::gridLatitude;
using testing::gridLongitude;
using testing::makeBlock;
const TileId kFigureTile{3, 5, 2};  // 67.5 W..45 W, 22.5 N..45 N

using testing::distinct;

// Random heights with no-data (sea), negatives and one spike (Everest) at (8, 8).
int16_t spiky(uint32_t i, uint32_t j) {
  if (i == 8 && j == 8) return 8848;
  const uint32_t k = (i * 131 + j * 71 + 7) % 23;
  if (k < 5) return terrain::kNoDataHeight;
  if (k < 8) return static_cast<int16_t>(-10 * static_cast<int>(k));
  return static_cast<int16_t>((i * 977 + j * 389) % 3000);
}

// An independent reading of the expected heights: no-data is 0 m.
double expected(const terrain::HeightBlock& block, uint32_t i, uint32_t j) {
  const int16_t sample = block.heights[i * kN + j];
  return sample == -9999 ? 0.0 : static_cast<double>(sample);
}

struct Fig3 : ::testing::TestWithParam<int> {
  terrain::HeightBlock block = makeBlock(kN, GetParam() == 0 ? distinct : spiky);
  RenderingTileArray array = testing::arrayOf({kFigureTile}, block);
  std::mt19937_64 rng{static_cast<uint64_t>(GetParam()) + 3};

  // Checks H through both QOTCD lookups (camera deep below, so the block is always read).
  void check(double lon, double lat, double h, HeightCase heightCase, const char* what) {
    for (int linear = 0; linear < 2; ++linear) {
      const geo::Cartographic camera{lon, lat, -20000.0};
      const QotcdResult r =
          linear ? qotcdLinear(array, camera, 0.0) : qotcdIndexed(array, camera, 0.0);
      ASSERT_TRUE(r.valid && r.found) << what;
      EXPECT_EQ(r.tile, kFigureTile);
      EXPECT_EQ(r.terrainHeightMeters, h) << what << " lon " << lon << " lat " << lat;
      EXPECT_EQ(r.heightCase, heightCase) << what << " lon " << lon << " lat " << lat;
      EXPECT_TRUE(r.collided);
      EXPECT_FALSE(r.earlyOut);
    }
  }
};

TEST_P(Fig3, EveryVertex) {
  const double eps = kGridEpsilonCells;
  for (uint32_t i = 0; i < kN; ++i) {
    for (uint32_t j = 0; j < kN; ++j) {
      const double h = expected(block, i, j);
      check(gridLongitude(kFigureTile, kN, j), gridLatitude(kFigureTile, kN, i), h,
            HeightCase::Vertex, "vertex");
      // The mesh's own vertex position (degrees), and points within the epsilon of the vertex.
      check(testing::meshVertexLongitude(kFigureTile, kN, j),
            testing::meshVertexLatitude(kFigureTile, kN, i), h, HeightCase::Vertex, "mesh vertex");
      const double dj = j == kN - 1 ? -0.5 * eps : 0.5 * eps;
      const double di = i == kN - 1 ? -0.9 * eps : 0.9 * eps;
      check(gridLongitude(kFigureTile, kN, j + dj), gridLatitude(kFigureTile, kN, i + di), h,
            HeightCase::Vertex, "near vertex");
    }
  }
}

TEST_P(Fig3, EveryRowAndColumnSegment) {
  std::uniform_real_distribution<double> fraction(3e-9, 1.0 - 3e-9);
  for (uint32_t line = 0; line < kN; ++line) {
    for (uint32_t k = 0; k + 1 < kN; ++k) {
      for (int sample = 0; sample < 8; ++sample) {
        const double t = sample == 0   ? 0.5
                         : sample == 1 ? 3e-9
                         : sample == 2 ? 1 - 3e-9
                                       : fraction(rng);
        // Row `line`, between columns k and k+1.
        check(gridLongitude(kFigureTile, kN, k + t), gridLatitude(kFigureTile, kN, line),
              std::max(expected(block, line, k), expected(block, line, k + 1)),
              HeightCase::RowOrColumn, "row");
        // Column `line`, between rows k and k+1.
        check(gridLongitude(kFigureTile, kN, line), gridLatitude(kFigureTile, kN, k + t),
              std::max(expected(block, k, line), expected(block, k + 1, line)),
              HeightCase::RowOrColumn, "column");
        // Within the epsilon of the line counts as on it.
        const double off = line == 0 ? 0.5e-9 : -0.5e-9;
        check(gridLongitude(kFigureTile, kN, k + t), gridLatitude(kFigureTile, kN, line + off),
              std::max(expected(block, line, k), expected(block, line, k + 1)),
              HeightCase::RowOrColumn, "near row");
      }
    }
  }
}

TEST_P(Fig3, EveryQuad) {
  std::uniform_real_distribution<double> fraction(3e-9, 1.0 - 3e-9);
  for (uint32_t i = 0; i + 1 < kN; ++i) {
    for (uint32_t j = 0; j + 1 < kN; ++j) {
      const double h = std::max({expected(block, i, j), expected(block, i, j + 1),
                                 expected(block, i + 1, j), expected(block, i + 1, j + 1)});
      for (int sample = 0; sample < 10; ++sample) {
        const double s = sample == 0 ? 0.5 : fraction(rng);
        const double t = sample == 0 ? 0.5 : fraction(rng);
        check(gridLongitude(kFigureTile, kN, j + t), gridLatitude(kFigureTile, kN, i + s), h,
              HeightCase::Quad, "quad");
      }
    }
  }
}

TEST_P(Fig3, JustBeyondTheEpsilonIsOffTheLine) {
  // 3e-9 of a cell from vertex (4, 6): in a quad, or on a line when only one axis is off.
  const double lon = gridLongitude(kFigureTile, kN, 6 + 3e-9);
  const double lat = gridLatitude(kFigureTile, kN, 4 + 3e-9);
  check(lon, lat,
        std::max({expected(block, 4, 6), expected(block, 4, 7), expected(block, 5, 6),
                  expected(block, 5, 7)}),
        HeightCase::Quad, "off vertex");
  check(lon, gridLatitude(kFigureTile, kN, 4),
        std::max(expected(block, 4, 6), expected(block, 4, 7)), HeightCase::RowOrColumn, "off");
  check(gridLongitude(kFigureTile, kN, 6 - 3e-9), gridLatitude(kFigureTile, kN, 4),
        std::max(expected(block, 4, 5), expected(block, 4, 6)), HeightCase::RowOrColumn, "off");
}

INSTANTIATE_TEST_SUITE_P(Patterns, Fig3, ::testing::Values(0, 1));

TEST(Fig3Spike, NoDataCountsAsSeaLevel) {
  // A quad of no-data and negative heights reads 0 m (sea), not -9999 or the negatives.
  const terrain::HeightBlock block = makeBlock(kN, [](uint32_t i, uint32_t j) {
    if ((i + j) % 2 == 0) return terrain::kNoDataHeight;
    return static_cast<int16_t>(-5 - static_cast<int>(i));
  });
  const ArrayTile tile = makeArrayTile(kFigureTile, block);
  EXPECT_EQ(tile.maximumHeightMeters, 0);
  const TileHeight quad = qotcdTileHeight(tile, gridLongitude(kFigureTile, kN, 3.3),
                                          gridLatitude(kFigureTile, kN, 7.6));
  EXPECT_EQ(quad.heightMeters, 0.0);
  const TileHeight vertex =
      qotcdTileHeight(tile, gridLongitude(kFigureTile, kN, 3), gridLatitude(kFigureTile, kN, 4));
  EXPECT_EQ(vertex.heightMeters, -9.0);  // (4, 3): odd sum, a real negative height
  const TileHeight sea =
      qotcdTileHeight(tile, gridLongitude(kFigureTile, kN, 3), gridLatitude(kFigureTile, kN, 5));
  EXPECT_EQ(sea.heightMeters, 0.0);
  const TileHeight segment =
      qotcdTileHeight(tile, gridLongitude(kFigureTile, kN, 3), gridLatitude(kFigureTile, kN, 4.5));
  EXPECT_EQ(segment.heightMeters, 0.0);  // max(-9, sea)
  EXPECT_EQ(segment.heightCase, HeightCase::RowOrColumn);
}

TEST(Fig3Edges, NeighbourTilesOnSharedEdgesAndCorners) {
  // The tile and its 8 neighbours at the same level, each with its own heights (base + 100 i + j),
  // so the chosen tile is visible in H. Real pyramids share edge vertices; here they differ.
  std::vector<terrain::HeightBlock> blocks;
  std::vector<TileId> ids;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      ids.push_back({3, static_cast<uint32_t>(5 + dx), static_cast<uint32_t>(2 + dy)});
      const int base = 3000 * static_cast<int>(ids.size());
      blocks.push_back(makeBlock(kN, [base](uint32_t i, uint32_t j) {
        return static_cast<int16_t>(base + static_cast<int>(100 * i + j));
      }));
    }
  }
  auto baseOf = [&](const TileId& id) { return 3000.0 * (3 * (id.y - 1) + (id.x - 4) + 1); };
  std::vector<ArrayTile> tiles;
  for (size_t k = 0; k < ids.size(); ++k) tiles.push_back(makeArrayTile(ids[k], blocks[k]));
  RenderingTileArray array;
  array.assign(tiles);
  // Each of the centre tile's 16 edge vertices per side and its corners: the owner by the
  // half-open rule is the east / south tile, read at its own vertex.
  for (uint32_t k = 0; k < kN; ++k) {
    struct Case {
      double lon, lat;
      TileId owner;
      double ownerRow, ownerColumn;
    };
    const Case cases[] = {
        // West, east, north and south edges; the south-west / south-east corners and the
        // south edge belong to the southern row, the east edge to the eastern column.
        {gridLongitude(kFigureTile, kN, 0),
         gridLatitude(kFigureTile, kN, k),
         {3, 5, k == kN - 1 ? 3u : 2u},
         k == kN - 1 ? 0.0 : static_cast<double>(k),
         0},
        {gridLongitude(kFigureTile, kN, kN - 1),
         gridLatitude(kFigureTile, kN, k),
         {3, 6, k == kN - 1 ? 3u : 2u},
         k == kN - 1 ? 0.0 : static_cast<double>(k),
         0},
        {gridLongitude(kFigureTile, kN, k),
         gridLatitude(kFigureTile, kN, 0),
         {3, k == kN - 1 ? 6u : 5u, 2},
         0,
         k == kN - 1 ? 0.0 : static_cast<double>(k)},
        {gridLongitude(kFigureTile, kN, k),
         gridLatitude(kFigureTile, kN, kN - 1),
         {3, k == kN - 1 ? 6u : 5u, 3},
         0,
         k == kN - 1 ? 0.0 : static_cast<double>(k)},
    };
    for (const Case& c : cases) {
      const double h = baseOf(c.owner) + 100 * c.ownerRow + c.ownerColumn;
      for (int linear = 0; linear < 2; ++linear) {
        const geo::Cartographic camera{c.lon, c.lat, -1e5};
        const QotcdResult r =
            linear ? qotcdLinear(array, camera, 0) : qotcdIndexed(array, camera, 0);
        EXPECT_EQ(r.tile, c.owner) << k;
        EXPECT_EQ(r.terrainHeightMeters, h) << k;
        EXPECT_EQ(r.heightCase, HeightCase::Vertex) << k;
      }
    }
  }
}

TEST(Fig3Edges, SharedEdgeWithAFinerNeighbourReadsTheFinerTile) {
  const terrain::HeightBlock coarse =
      makeBlock(kN, [](uint32_t, uint32_t) { return int16_t{100}; });
  const terrain::HeightBlock fine =
      makeBlock(kN, [](uint32_t i, uint32_t j) { return static_cast<int16_t>(200 + 100 * i + j); });
  // East of (3,5,2) lie (4,12,4) and (4,12,5).
  RenderingTileArray array;
  array.assign({makeArrayTile(kFigureTile, coarse), makeArrayTile({4, 12, 4}, fine),
                makeArrayTile({4, 12, 5}, fine)});
  const double lon = gridLongitude(kFigureTile, kN, kN - 1);
  // Coarse vertex row 4 = fine (4,12,4) row 8; coarse row 10 = fine (4,12,5) row 4; coarse
  // row 4.5 = fine row 9, a vertex there.
  const double split = geo::GeographicTilingScheme::tileRectangle({4, 12, 5}).northRadians;
  const struct {
    double latitude;
    TileId tile;
    double h;
    HeightCase heightCase;
  } cases[] = {
      {gridLatitude(kFigureTile, kN, 4), {4, 12, 4}, 200 + 800, HeightCase::Vertex},
      {gridLatitude(kFigureTile, kN, 10), {4, 12, 5}, 200 + 400, HeightCase::Vertex},
      {gridLatitude(kFigureTile, kN, 4.5), {4, 12, 4}, 200 + 900, HeightCase::Vertex},
      {gridLatitude(kFigureTile, kN, 4.25), {4, 12, 4}, 200 + 900, HeightCase::RowOrColumn},
      {split, {4, 12, 5}, 200, HeightCase::Vertex},
      {std::nextafter(split, 1.0), {4, 12, 4}, 200 + 1600, HeightCase::Vertex}};
  for (const auto& c : cases) {
    for (int linear = 0; linear < 2; ++linear) {
      const geo::Cartographic camera{lon, c.latitude, -1e5};
      const QotcdResult r = linear ? qotcdLinear(array, camera, 0) : qotcdIndexed(array, camera, 0);
      EXPECT_EQ(r.tile, c.tile) << c.latitude;
      EXPECT_EQ(r.terrainHeightMeters, c.h) << c.latitude;
      EXPECT_EQ(r.heightCase, c.heightCase) << c.latitude;
    }
  }
}

}  // namespace
}  // namespace globe::collision
