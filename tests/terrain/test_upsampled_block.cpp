// Blocks made from their parent's surface: parent vertices kept, neighbours (across tiles, ±180°
// and two generations deep) agreeing on shared edges, aprons and normals, water kept, old blocks
// without an apron, height bounds that hold the exact heights, and shading that continues the
// parent's (its normals, colours and water interpolated, not the child's own faceted normals).
#include "terrain/upsampled_block.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "terrain/tile_mesh.hpp"
#include "tests/support/test_constants.hpp"
#include "tests/terrain/upsampled_test_world.hpp"

namespace globe::terrain {
namespace {

using globe::test::kN;
using globe::test::kWgs84;
using globe::testing::upsampledWorldBlock;

HeightBlock childOf(const geo::TileId& parent, const geo::TileId& child) {
  return upsampleBlock(upsampledWorldBlock(parent, kN), child, kWgs84);
}

TEST(UpsampledBlock, KeepsTheParentsVerticesAndItsWater) {
  const geo::TileId parent{5, 40, 9};
  const HeightBlock block = upsampledWorldBlock(parent, kN);
  for (const geo::TileId& child : parent.children()) {
    const HeightBlock up = upsampleBlock(block, child, kWgs84);
    ASSERT_EQ(up.exactSurfaceMeters.size(), kN * kN);
    ASSERT_TRUE(up.hasApron());
    const uint32_t rowOffset = (child.y & 1u) * (kN - 1) / 2;
    const uint32_t columnOffset = (child.x & 1u) * (kN - 1) / 2;
    for (uint32_t i = 0; i < kN; i += 2) {
      for (uint32_t j = 0; j < kN; j += 2) {
        const uint32_t pi = rowOffset + i / 2, pj = columnOffset + j / 2;
        EXPECT_EQ(up.surfaceHeightMetersAt(i, j), block.surfaceHeightMetersAt(pi, pj));
        EXPECT_EQ(up.at(i, j), block.at(pi, pj));
      }
    }
    // Between two water vertices the sample stays water; heights stay finite everywhere.
    for (uint32_t i = 0; i + 2 < kN; i += 2) {
      for (uint32_t j = 0; j < kN; j += 2) {
        const uint32_t pi = rowOffset + i / 2, pj = columnOffset + j / 2;
        if (isWater(block.at(pi, pj)) && isWater(block.at(pi + 1, pj))) {
          EXPECT_TRUE(isWater(up.at(i + 1, j)));
        }
      }
    }
    for (double h : up.exactSurfaceMeters) EXPECT_TRUE(std::isfinite(h));
    for (double h : up.exactApronSurfaceMeters) EXPECT_TRUE(std::isfinite(h));
  }
}

// The children of two neighbouring parents (and theirs again) compute identical heights for
// their shared edge, their aprons hold the neighbour's heights, and their meshes identical
// normals there: no crack and no lighting step where the upsampled tiles meet.
// Bit for bit, but across ±180° where sin(±pi) puts the two meshes' edge ~1e-9 m apart.
void expectNeighboursAgree(const geo::TileId& west, const HeightBlock& westBlock,
                           const geo::TileId& east, const HeightBlock& eastBlock,
                           double toleranceMeters = 0.0) {
  const auto last = static_cast<int>(kN) - 1;
  for (int i = 0; i <= last; ++i) {
    EXPECT_NEAR(westBlock.surfaceHeightMetersWithApron(i, last),
                eastBlock.surfaceHeightMetersWithApron(i, 0), toleranceMeters)
        << "row " << i;
    for (int k = 1; k <= kApronWidth; ++k) {
      EXPECT_NEAR(westBlock.surfaceHeightMetersWithApron(i, last + k),
                  eastBlock.surfaceHeightMetersWithApron(i, k), toleranceMeters);
      EXPECT_NEAR(eastBlock.surfaceHeightMetersWithApron(i, -k),
                  westBlock.surfaceHeightMetersWithApron(i, last - k), toleranceMeters);
    }
  }
  const TileMesh westMesh = buildTileMesh(west, westBlock, kWgs84, 0.0);
  const TileMesh eastMesh = buildTileMesh(east, eastBlock, kWgs84, 0.0);
  for (uint32_t i = 0; i < kN; ++i) {
    const float* a = &westMesh.vertices[gridVertexIndex(i, kN - 1, kN) * kTileVertexFloats +
                                        kTileVertexNormalOffset];
    const float* b =
        &eastMesh.vertices[gridVertexIndex(i, 0, kN) * kTileVertexFloats + kTileVertexNormalOffset];
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-6f) << "row " << i;
  }
}

TEST(UpsampledBlock, NeighboursAgreeOnSharedEdgesApronsAndNormals) {
  // Across a parent boundary at level 5, inside one parent, and across ±180°.
  const geo::TileId westParent{5, 40, 9}, eastParent{5, 41, 9};
  const geo::TileId westChild{6, 81, 18}, eastChild{6, 82, 18};
  const HeightBlock west = childOf(westParent, westChild);
  const HeightBlock east = childOf(eastParent, eastChild);
  expectNeighboursAgree(westChild, west, eastChild, east);
  expectNeighboursAgree(geo::TileId{6, 80, 18}, childOf(westParent, {6, 80, 18}), westChild, west);
  // Two generations: grandchildren of neighbouring parents.
  const geo::TileId westGrand{7, 163, 37}, eastGrand{7, 164, 37};
  expectNeighboursAgree(westGrand, upsampleBlock(west, westGrand, kWgs84), eastGrand,
                        upsampleBlock(east, eastGrand, kWgs84));
  const uint32_t lastColumn = (2u << 5) - 1;  // level 5: 64 columns
  const geo::TileId wrapWest{6, 2 * lastColumn + 1, 18}, wrapEast{6, 0, 18};
  expectNeighboursAgree(wrapWest, childOf({5, lastColumn, 9}, wrapWest), wrapEast,
                        childOf({5, 0, 9}, wrapEast), 1e-6);
}

TEST(UpsampledBlock, PolarTilesStayFinite) {
  for (const geo::TileId& parent : {geo::TileId{3, 5, 0}, geo::TileId{3, 5, 7}}) {
    for (const geo::TileId& child : parent.children()) {
      const HeightBlock up = childOf(parent, child);
      for (double h : up.exactSurfaceMeters) ASSERT_TRUE(std::isfinite(h));
      for (double h : up.exactApronSurfaceMeters) ASSERT_TRUE(std::isfinite(h));
      const TileMesh mesh = buildTileMesh(child, up, kWgs84, 100.0);
      for (float v : mesh.vertices) ASSERT_TRUE(std::isfinite(v));
    }
  }
}

TEST(UpsampledBlock, ABlockWithoutApronGivesOneWithout) {
  const geo::TileId parent{5, 40, 9};
  const HeightBlock block = upsampledWorldBlock(parent, kN, false);
  for (const geo::TileId& child : parent.children()) {
    const HeightBlock up = upsampleBlock(block, child, kWgs84);
    EXPECT_FALSE(up.hasApron());
    EXPECT_TRUE(up.exactApronSurfaceMeters.empty());
    for (double h : up.exactSurfaceMeters) EXPECT_TRUE(std::isfinite(h));
  }
}

TEST(UpsampledBlock, HeightBoundsHoldTheExactHeights) {
  const geo::TileId parent{5, 40, 9};
  for (const geo::TileId& child : parent.children()) {
    const HeightBlock up = childOf(parent, child);
    const HeightRange range = surfaceHeightRange(up);
    for (double h : up.exactSurfaceMeters) {
      EXPECT_LE(range.minimumMeters, h);
      EXPECT_GE(range.maximumMeters, h);
    }
  }
}

// The mesh values (normal, colour height, water) of grid vertex (row, column).
struct Shading {
  glm::dvec3 normal;
  double colorMeters;
  double water;
};
Shading shadingAt(const TileMesh& mesh, uint32_t row, uint32_t column) {
  const float* v =
      &mesh.vertices[gridVertexIndex(row, column, mesh.verticesPerSide) * kTileVertexFloats];
  return {
      {v[kTileVertexNormalOffset], v[kTileVertexNormalOffset + 1], v[kTileVertexNormalOffset + 2]},
      v[kTileVertexHeightOffset],
      v[kTileVertexSeaOffset]};
}

TEST(UpsampledBlock, ShadedAsTheParentsTrianglesShadeThatGround) {
  int coasts = 0;
  for (const geo::TileId& parent : {geo::TileId{5, 40, 9}, geo::TileId{4, 3, 5},
                                    geo::TileId{4, 20, 3}, geo::TileId{4, 9, 11}}) {
    const HeightBlock block = upsampledWorldBlock(parent, kN);
    const TileMesh parentMesh = buildTileMesh(parent, block, kWgs84, 0.0);
    for (const geo::TileId& child : parent.children()) {
      const HeightBlock up = upsampleBlock(block, child, kWgs84);
      const TileMesh mesh = buildTileMesh(child, up, kWgs84, 0.0);
      const uint32_t rowOffset = (child.y & 1u) * (kN - 1),
                     columnOffset = (child.x & 1u) * (kN - 1);
      for (uint32_t i = 0; i < kN; ++i) {
        for (uint32_t j = 0; j < kN; ++j) {
          // The parent's two vertices at the ends of the edge this vertex halves (or one vertex).
          const uint32_t rowTwice = rowOffset + i, columnTwice = columnOffset + j;
          const Shading a = shadingAt(parentMesh, rowTwice / 2, columnTwice / 2);
          const Shading b =
              shadingAt(parentMesh, rowTwice / 2 + rowTwice % 2, columnTwice / 2 + columnTwice % 2);
          const Shading c = shadingAt(mesh, i, j);
          EXPECT_GT(glm::dot(c.normal, glm::normalize(a.normal + b.normal)), 1.0 - 1e-6)
              << child.x << "," << child.y << " " << i << "," << j;
          EXPECT_NEAR(c.colorMeters, 0.5 * (a.colorMeters + b.colorMeters), 0.01);
          EXPECT_DOUBLE_EQ(c.water, 0.5 * (a.water + b.water));
          coasts += c.water == 0.5 ? 1 : 0;
        }
      }
    }
  }
  EXPECT_GT(coasts, 0);  // the test world's coasts run through some of these tiles
}

TEST(UpsampledBlock, GrandchildrenKeepTheGrandparentsShading) {
  // Two generations: the grandchild's shading still interpolates the grandparent's, so a tile
  // refined twice looks like the real block it came from.
  const geo::TileId parent{5, 40, 9};
  const HeightBlock block = upsampledWorldBlock(parent, kN);
  const geo::TileId child = parent.children()[0];
  const geo::TileId grandchild = child.children()[3];
  const HeightBlock up = upsampleBlock(upsampleBlock(block, child, kWgs84), grandchild, kWgs84);
  const TileMesh parentMesh = buildTileMesh(parent, block, kWgs84, 0.0);
  const TileMesh mesh = buildTileMesh(grandchild, up, kWgs84, 0.0);
  // Grandchild (north-west child's south-east child) vertex 0,0 is the parent's (kN-1)/4 point.
  const uint32_t quarter = (kN - 1) / 4;
  const Shading parentVertex = shadingAt(parentMesh, quarter, quarter);
  const Shading own = shadingAt(mesh, 0, 0);
  EXPECT_GT(glm::dot(own.normal, parentVertex.normal), 1.0 - 1e-6);
  EXPECT_NEAR(own.colorMeters, parentVertex.colorMeters, 0.01);
  EXPECT_EQ(own.water, parentVertex.water);
}

}  // namespace
}  // namespace globe::terrain
