// The tiler's per-tile extras, checked on the bundled pyramid: each block's apron holds its
// neighbours' vertices (so meshes of neighbouring tiles get identical edge normals), and each
// tile's geometric error bounds how far its surface lies from its children's vertices and is at
// least their errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <glm/geometric.hpp>

#include "geo/ellipsoid.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/height_block.hpp"
#include "terrain/screen_space_error.hpp"
#include "terrain/tile_mesh.hpp"
#include "tests/support/bundled_pyramid_blocks.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::tiling {

using globe::testing::BundledPyramid;
namespace {

// Calls visit(row, column) for every position of the apron.
template <class Visit>
void forEachApronPosition(uint32_t verticesPerSide, Visit visit) {
  const auto side = static_cast<int>(verticesPerSide);
  constexpr int w = terrain::kApronWidth;
  for (int row = -w; row < side + w; ++row) {
    for (int column = -w; column < side + w; ++column) {
      if (row < 0 || row >= side || column < 0 || column >= side) visit(row, column);
    }
  }
}

// The level's global vertex indices of a position (exact: vertex positions are dyadic).
struct GlobalVertex {
  int64_t row, column;
};
GlobalVertex globalVertexOf(uint32_t level, uint32_t verticesPerSide,
                            const terrain::BlockGrid::Vertex& where) {
  const double spacing = terrain::vertexSpacingDegrees(level, verticesPerSide);
  return {std::llround((90.0 - where.latitudeDegrees) / spacing),
          std::llround((where.longitudeDegrees + 180.0) / spacing)};
}

TEST_F(BundledPyramid, ApronHoldsWhatTheNeighbouringTilesHold) {
  const globe::testing::Oracle oracle(globe::testing::bundledInputs());
  uint64_t checked = 0, againstNeighbours = 0, mismatches = 0;
  for (const auto& [tile, block] : *tiles_) {
    ASSERT_EQ(block.apron.size(), terrain::apronSampleCount(n));
    const terrain::BlockGrid grid{tile, n};
    const int64_t columns = int64_t{geo::GeographicTilingScheme::tilesX(tile.level)} * (n - 1);
    forEachApronPosition(n, [&](int row, int column) {
      const int16_t apron = block.apron[terrain::apronIndex(row, column, n)];
      const terrain::BlockGrid::Vertex where = grid.wrappedVertex(row, column);
      ++checked;
      const int16_t expected = oracle.height(where.longitudeDegrees, where.latitudeDegrees);
      if (apron != expected && ++mismatches < 10) {
        ADD_FAILURE() << "tile " << tile.level << "/" << tile.x << "/" << tile.y << " apron ("
                      << row << "," << column << "): " << apron << " != oracle " << expected;
      }
      // Every tile of the level that holds that vertex holds the same sample.
      const GlobalVertex v = globalVertexOf(tile.level, n, where);
      for (int64_t x : {v.column / (n - 1), v.column / (n - 1) - 1}) {
        for (int64_t y : {v.row / (n - 1), v.row / (n - 1) - 1}) {
          if (x < 0 || y < 0) continue;
          const auto tx = static_cast<uint32_t>(x % (columns / (n - 1)));
          const Block* holder = findBlock({tile.level, tx, static_cast<uint32_t>(y)});
          const int64_t i = v.row - y * (n - 1);
          int64_t j = v.column - x * (n - 1);
          if (holder == nullptr || i < 0 || i >= n || j < 0 || j >= n) continue;
          ++againstNeighbours;
          if (holder->samples[static_cast<size_t>(i * n + j)] != apron && ++mismatches < 10) {
            ADD_FAILURE() << "tile " << tile.level << "/" << tile.x << "/" << tile.y << " apron ("
                          << row << "," << column << ") differs from tile " << tile.level << "/"
                          << tx << "/" << y;
          }
        }
      }
    });
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_GT(checked, 1'500'000u);  // ~24,000 tiles
  EXPECT_GT(againstNeighbours, 1'500'000u);
}

// The tile's surface at grid position (row, column) in vertex units, with the mesh's diagonal
// rule, by barycentric interpolation over the triangle that holds the point.
double surfaceAt(const std::vector<int16_t>& samples, terrain::SeaSurface sea, double row,
                 double column) {
  const auto i = std::min<uint32_t>(static_cast<uint32_t>(row), 15);
  const auto j = std::min<uint32_t>(static_cast<uint32_t>(column), 15);
  const double v = row - i, u = column - j;
  auto h = [&](uint32_t r, uint32_t c) {
    return terrain::surfaceHeightMeters(samples[r * 17 + c], sea);
  };
  // South-west triangle (i,j),(i+1,j),(i+1,j+1) where u <= v, else (i,j),(i+1,j+1),(i,j+1).
  if (u <= v) return (1 - v) * h(i, j) + (v - u) * h(i + 1, j) + u * h(i + 1, j + 1);
  return (1 - u) * h(i, j) + v * h(i + 1, j + 1) + (u - v) * h(i, j + 1);
}

TEST_F(BundledPyramid, GeometricErrorBoundsAllButTheLargestDeviationsAndNeverDecreasesUpwards) {
  const geo::Ellipsoid kWgs84 = geo::Ellipsoid::wgs84();
  uint64_t parents = 0, leaves = 0, coasts = 0;
  uint64_t skewed = 0;  // children whose largest deviation is far beyond the rest
  double largest = 0;
  for (const auto& [tile, block] : *tiles_) {
    const float error = block.entry.geometricErrorMeters;
    ASSERT_TRUE(std::isfinite(error) && error >= 0.0f);
    const auto children = tile.children();
    if (findBlock(children[0]) == nullptr) {
      EXPECT_EQ(error, 0.0f) << "a tile of the finest data";
      ++leaves;
      continue;
    }
    ++parents;
    largest = std::max(largest, double{error});
    bool water = false, land = false;
    for (const geo::TileId& child : children) {
      for (const int16_t sample : findBlock(child)->samples) {
        (terrain::isWater(sample) ? water : land) = true;
      }
    }
    if (water && land) {  // a coast: its shape is in the sea flags, so it refines as before
      ++coasts;
      EXPECT_GE(double{error}, terrain::geometricErrorMeters(tile.level, n, kWgs84))
          << tile.level << "/" << tile.x << "/" << tile.y;
    }
    double boundOfAll = 0;  // the largest deviation or child error: the rule never exceeds it
    for (size_t q = 0; q < 4; ++q) {
      const Block* child = findBlock(children[q]);
      ASSERT_NE(child, nullptr);
      const double rowOffset = (q >= 2 ? 8.0 : 0.0), columnOffset = (q % 2 == 1 ? 8.0 : 0.0);
      std::vector<double> deviations;  // of the child's vertices that the parent does not have
      for (uint32_t i = 0; i < n; ++i) {
        for (uint32_t j = 0; j < n; ++j) {
          if (i % 2 == 0 && j % 2 == 0) continue;
          double deviation = 0;
          for (const auto sea : {terrain::SeaSurface::Water, terrain::SeaSurface::SeaFloor}) {
            const double fine = terrain::surfaceHeightMeters(child->samples[i * n + j], sea);
            deviation = std::max(deviation,
                                 std::abs(fine - surfaceAt(block.samples, sea, rowOffset + i / 2.0,
                                                           columnOffset + j / 2.0)));
          }
          deviations.push_back(deviation);
        }
      }
      std::sort(deviations.begin(), deviations.end(), std::greater<>());
      // All but the largest 3 % (of 208: the 6 largest) lie within the error, and the largest
      // within 2.5 times it (pack_builder.hpp).
      const size_t ignored = deviations.size() * 3 / 100;
      const double childError = child->entry.geometricErrorMeters;
      const double required = std::max({deviations[ignored], 0.4 * deviations.front(), childError});
      ASSERT_GE(double{error}, required - 1e-3)
          << tile.level << "/" << tile.x << "/" << tile.y << " child " << q;
      boundOfAll = std::max({boundOfAll, deviations.front(), childError});
      if (deviations.front() > 2.5 * deviations[ignored] + 1.0) ++skewed;
    }
    if (!(water && land)) {
      // Stored as a float rounded up (one step per level it is carried up).
      EXPECT_LE(double{error}, boundOfAll * (1 + 1e-6) + 1e-3)
          << tile.level << "/" << tile.x << "/" << tile.y;
    }
  }
  EXPECT_GT(parents, 5'000u);
  EXPECT_GT(leaves, 15'000u);
  EXPECT_GT(largest, 500.0);  // the sea floor and Fuji are anything but flat
  EXPECT_GT(coasts, 100u);
  EXPECT_GT(skewed, 10u);  // the 0.4 x largest bound is exercised, not only the 97th percentile
}

terrain::HeightBlock heightBlockOf(const globe::testing::BundledPyramid::Block* block) {
  return {17, block->samples, terrain::SeaSurface::Water, block->apron};
}

TEST_F(BundledPyramid, NeighboursMeshesHaveIdenticalNormalsOnTheirSharedEdge) {
  const geo::Ellipsoid ellipsoid = geo::Ellipsoid::wgs84();
  uint64_t edges = 0;
  double worstDegrees = 0;
  auto normalAt = [](const terrain::TileMesh& mesh, uint32_t row, uint32_t column) {
    const float* v =
        &mesh.vertices[terrain::gridVertexIndex(row, column, 17) * terrain::kTileVertexFloats +
                       terrain::kTileVertexNormalOffset];
    return glm::dvec3(v[0], v[1], v[2]);
  };
  for (const auto& [tile, block] : *tiles_) {
    // Every level, the antimeridian (x wraps), and many tiles elsewhere.
    if (tile.level > 8 && (tile.x + tile.y) % 7 != 0) continue;
    const uint32_t nx = geo::GeographicTilingScheme::tilesX(tile.level);
    const Block* east = findBlock({tile.level, (tile.x + 1) % nx, tile.y});
    const Block* south = findBlock({tile.level, tile.x, tile.y + 1});
    if (east == nullptr && south == nullptr) continue;
    const terrain::TileMesh here =
        terrain::buildTileMesh(tile, heightBlockOf(&block), ellipsoid, 0);
    auto compare = [&](const terrain::TileMesh& other, bool eastEdge) {
      for (uint32_t k = 0; k < n; ++k) {
        const glm::dvec3 a = eastEdge ? normalAt(here, k, n - 1) : normalAt(here, n - 1, k);
        const glm::dvec3 b = eastEdge ? normalAt(other, k, 0) : normalAt(other, 0, k);
        const double cosine =
            std::clamp(glm::dot(a, b) / (glm::length(a) * glm::length(b)), -1.0, 1.0);
        worstDegrees = std::max(worstDegrees, std::acos(cosine) * 180.0 / 3.141592653589793);
      }
      ++edges;
    };
    if (east != nullptr) {
      compare(terrain::buildTileMesh({tile.level, (tile.x + 1) % nx, tile.y}, heightBlockOf(east),
                                     ellipsoid, 0),
              true);
    }
    if (south != nullptr) {
      compare(terrain::buildTileMesh({tile.level, tile.x, tile.y + 1}, heightBlockOf(south),
                                     ellipsoid, 0),
              false);
    }
  }
  EXPECT_GT(edges, 5'000u);
  // Same heights, same positions, same arithmetic: equal to float rounding (at ±180° the
  // longitude is -180 on one side and +180 on the other: sines differ in the last bit).
  EXPECT_LT(worstDegrees, 1e-4);
}

// Across a level change: where a tile's neighbour is drawn one level coarser, the tile's edge is
// lit with its coarse normals (terrain/tile_mesh.hpp); those equal the coarser tile's own normals
// at its vertices, and the mean of the two around in between.
TEST_F(BundledPyramid, CoarseEdgeNormalsEqualTheCoarserNeighboursNormals) {
  const geo::Ellipsoid ellipsoid = geo::Ellipsoid::wgs84();
  auto vec = [](const terrain::TileMesh& mesh, uint32_t row, uint32_t column, uint32_t offset) {
    const float* v =
        &mesh.vertices[terrain::gridVertexIndex(row, column, 17) * terrain::kTileVertexFloats +
                       offset];
    return glm::dvec3(v[0], v[1], v[2]);
  };
  auto degreesBetween = [](const glm::dvec3& a, const glm::dvec3& b) {
    const double cosine = std::clamp(glm::dot(a, b) / (glm::length(a) * glm::length(b)), -1.0, 1.0);
    return std::acos(cosine) * 180.0 / 3.141592653589793;
  };
  uint64_t even = 0, odd = 0;
  double worstEven = 0, worstOdd = 0;
  const int64_t cells = n - 1;
  for (const auto& [tile, block] : *tiles_) {
    if (tile.level == 0 || (tile.level > 8 && (tile.x + tile.y) % 5 != 0)) continue;
    const int64_t columnsAround = int64_t{geo::GeographicTilingScheme::tilesX(tile.level)} * cells;
    const uint32_t nx = geo::GeographicTilingScheme::tilesX(tile.level);
    // The east and south neighbours when they belong to another parent.
    const geo::TileId east{tile.level, (tile.x + 1) % nx, tile.y};
    const geo::TileId south{tile.level, tile.x, tile.y + 1};
    for (const auto& [neighbour, eastEdge] : {std::pair{east, true}, std::pair{south, false}}) {
      if (findBlock(neighbour) == nullptr || neighbour.parent() == tile.parent()) continue;
      const geo::TileId coarser = neighbour.parent();
      const Block* coarseBlock = findBlock(coarser);
      ASSERT_NE(coarseBlock, nullptr);
      const auto fine = terrain::buildTileMesh(tile, heightBlockOf(&block), ellipsoid, 0);
      const auto coarse = terrain::buildTileMesh(coarser, heightBlockOf(coarseBlock), ellipsoid, 0);
      for (uint32_t k = 0; k < n; ++k) {
        const uint32_t row = eastEdge ? k : n - 1, column = eastEdge ? n - 1 : k;
        // The coarser tile's vertex at this point, in its own indices (global indices halve).
        const int64_t globalRow = int64_t{tile.y} * cells + row;
        const int64_t globalColumn = (int64_t{tile.x} * cells + column) % columnsAround;
        auto coarseNormalAt = [&](int64_t gRow, int64_t gColumn) {
          int64_t i = gRow / 2 - int64_t{coarser.y} * cells;
          int64_t j = gColumn / 2 - int64_t{coarser.x} * cells;
          if (j < 0) j += columnsAround / 2;
          EXPECT_TRUE(i >= 0 && i < n && j >= 0 && j < n) << i << "," << j;
          return vec(coarse, static_cast<uint32_t>(i), static_cast<uint32_t>(j),
                     terrain::kTileVertexNormalOffset);
        };
        const glm::dvec3 mine = vec(fine, row, column, terrain::kTileVertexCoarseNormalOffset);
        if (globalRow % 2 == 0 && globalColumn % 2 == 0) {
          worstEven =
              std::max(worstEven, degreesBetween(mine, coarseNormalAt(globalRow, globalColumn)));
          ++even;
        } else {
          const glm::dvec3 mean = eastEdge ? coarseNormalAt(globalRow - 1, globalColumn) +
                                                 coarseNormalAt(globalRow + 1, globalColumn)
                                           : coarseNormalAt(globalRow, globalColumn - 1) +
                                                 coarseNormalAt(globalRow, globalColumn + 1);
          worstOdd = std::max(worstOdd, degreesBetween(mine, mean));
          ++odd;
        }
      }
    }
  }
  EXPECT_GT(even, 10'000u);
  EXPECT_GT(odd, 10'000u);
  EXPECT_LT(worstEven, 1e-4);  // the same vertices and arithmetic: float rounding only
  EXPECT_LT(worstOdd, 1e-4);
}

TEST_F(BundledPyramid, WithoutTheApronEdgeNormalsDisagree) {
  // The contrast that shows the test above can fail: one-sided differences on the edges.
  const geo::Ellipsoid ellipsoid = geo::Ellipsoid::wgs84();
  double worstDegrees = 0;
  for (const auto& [id, block] : *tiles_) {
    if (id.level != 13) continue;
    const Block* east = findBlock({id.level, id.x + 1, id.y});
    if (east == nullptr) continue;
    terrain::HeightBlock a = heightBlockOf(&block), b = heightBlockOf(east);
    a.apron.clear();
    b.apron.clear();
    const auto meshA = terrain::buildTileMesh(id, a, ellipsoid, 0);
    const auto meshB = terrain::buildTileMesh({id.level, id.x + 1, id.y}, b, ellipsoid, 0);
    for (uint32_t k = 0; k < n; ++k) {
      const float* p =
          &meshA.vertices[terrain::gridVertexIndex(k, n - 1, n) * terrain::kTileVertexFloats +
                          terrain::kTileVertexNormalOffset];
      const float* q =
          &meshB.vertices[terrain::gridVertexIndex(k, 0, n) * terrain::kTileVertexFloats +
                          terrain::kTileVertexNormalOffset];
      const double cosine =
          std::clamp(double{p[0]} * q[0] + double{p[1]} * q[1] + double{p[2]} * q[2], -1.0, 1.0);
      worstDegrees = std::max(worstDegrees, std::acos(cosine) * 180.0 / 3.141592653589793);
    }
  }
  EXPECT_GT(worstDegrees, 5.0) << "Fuji's flanks at level 13 are steep enough to show it";
}

}  // namespace
}  // namespace globe::tiling
