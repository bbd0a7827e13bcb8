// Watertight seams between tiles of one level: the GPU's position of a shared edge vertex is the
// same float vector in both tiles (emulated here exactly as terrain.vert forms it: origin +
// offset in float, then the level's matrix), and a skirt hangs wherever two neighbours draw their
// shared edge at different heights (a tile made from its parent's surface beside a pyramid one).
#include <gtest/gtest.h>

#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/edge_heights.hpp"
#include "terrain/skirt_edges.hpp"
#include "terrain/tile_mesh.hpp"
#include "terrain/tile_transform.hpp"
#include "terrain/upsampled_block.hpp"
#include "tests/support/test_constants.hpp"
#include "tests/terrain/upsampled_test_world.hpp"

namespace globe::terrain {
namespace {

using globe::test::kN;
using globe::test::kWgs84;
using globe::testing::upsampledWorldBlock;

// What terrain.vert hands the matrices for mesh vertex `vertex`: u_tileOrigin + a_offset, in float.
glm::vec3 gpuSum(const TileTransform& transform, const TileMesh& mesh, uint32_t vertex) {
  const float* v = &mesh.vertices[size_t{vertex} * kTileVertexFloats + kTileVertexPositionOffset];
  return transform.origin + glm::vec3(v[0], v[1], v[2]);
}

RenderView viewFrom(double lonDegrees, double latDegrees, double heightMeters) {
  const glm::dvec3 eye = geo::cartographicToEcef(
      kWgs84, geo::Cartographic::fromDegrees(lonDegrees, latDegrees, heightMeters));
  const glm::dvec3 target = geo::cartographicToEcef(
      kWgs84, geo::Cartographic::fromDegrees(lonDegrees, latDegrees - 0.01, 0.0));
  return makeLookAtView(eye, target, glm::dvec3(0.0, 0.0, 1.0), 0.7, 1280, 720,
                        glm::dvec3(1.0, 0.0, 0.0));
}

// Every shared edge vertex of a tile and its east and south neighbours, seen from `view`.
void expectBitIdenticalEdges(const geo::TileId& tile, const RenderView& view) {
  const uint32_t columns = geo::GeographicTilingScheme::tilesX(tile.level);
  const geo::TileId east{tile.level, (tile.x + 1) % columns, tile.y};
  const geo::TileId south{tile.level, tile.x, tile.y + 1};
  const TileMesh a = buildTileMesh(tile, upsampledWorldBlock(tile, kN), kWgs84, 40.0);
  const TileMesh b = buildTileMesh(east, upsampledWorldBlock(east, kN), kWgs84, 40.0);
  const TileMesh c = buildTileMesh(south, upsampledWorldBlock(south, kN), kWgs84, 40.0);
  const TileTransform ta = tileTransform(view, tile.level, a.centerEcefMeters);
  const TileTransform tb = tileTransform(view, tile.level, b.centerEcefMeters);
  const TileTransform tc = tileTransform(view, tile.level, c.centerEcefMeters);
  ASSERT_TRUE(ta.exact && tb.exact && tc.exact) << geo::tileName(tile);
  EXPECT_EQ(ta.levelView, tb.levelView);
  for (uint32_t k = 0; k < kN; ++k) {
    EXPECT_EQ(gpuSum(ta, a, gridVertexIndex(k, kN - 1, kN)),
              gpuSum(tb, b, gridVertexIndex(k, 0, kN)))
        << geo::tileName(tile) << " east edge " << k;
    EXPECT_EQ(gpuSum(ta, a, gridVertexIndex(kN - 1, k, kN)),
              gpuSum(tc, c, gridVertexIndex(0, k, kN)))
        << geo::tileName(tile) << " south edge " << k;
  }
}

TEST(WatertightSeams, SharedEdgeVerticesAreBitIdenticalOnTheGpu) {
  // Near the ground, high up, over the antimeridian (east of the last column is column 0) and
  // beside the north pole, at coarse and fine levels.
  struct Case {
    geo::TileId tile;
    double lon, lat, height;
  };
  const Case cases[] = {
      {{13, 9000, 3000}, 17.8, 24.1, 1500.0}, {{16, 72000, 24000}, 17.8, 24.1, 300.0},
      {{8, 511, 100}, 179.9, 20.0, 80000.0},  {{10, 300, 0}, -75.0, 89.9, 20000.0},
      {{3, 5, 1}, 50.0, 30.0, 2.0e7},         {{0, 0, 0}, 138.0, 30.0, 2.0e7},
  };
  for (const Case& c : cases) {
    const geo::GlobeRectangle r = geo::GeographicTilingScheme::tileRectangle(c.tile);
    const double lon = geo::radiansToDegrees(0.5 * (r.westRadians + r.eastRadians));
    const double lat = geo::radiansToDegrees(0.5 * (r.southRadians + r.northRadians));
    // The case's own camera and one straight over the tile.
    expectBitIdenticalEdges(c.tile, viewFrom(c.lon, c.lat, c.height));
    expectBitIdenticalEdges(c.tile, viewFrom(lon, lat, c.height));
  }
}

TEST(WatertightSeams, TooFarForExactFloatsIsSaid) {
  const geo::TileId tile{14, 16000, 5000};
  const TileMesh mesh = buildTileMesh(tile, upsampledWorldBlock(tile, kN), kWgs84, 0.0);
  // 2^24 origin quanta (1.6 cm) is 262 km: from 20,000 km the origin cannot be exact.
  EXPECT_FALSE(tileTransform(viewFrom(0.0, 0.0, 2.0e7), tile.level, mesh.centerEcefMeters).exact);
}

TEST(WatertightSeams, EdgeHashesAgreeAcrossPyramidNeighboursAndNotBesideAnUpsampledTile) {
  const geo::TileId tile{9, 300, 100}, east{9, 301, 100}, south{9, 300, 101};
  const EdgeHeightHashes a = edgeHeightHashes(upsampledWorldBlock(tile, kN));
  const EdgeHeightHashes b = edgeHeightHashes(upsampledWorldBlock(east, kN));
  const EdgeHeightHashes c = edgeHeightHashes(upsampledWorldBlock(south, kN));
  EXPECT_EQ(a[static_cast<int>(TileEdge::East)], b[static_cast<int>(TileEdge::West)]);
  EXPECT_EQ(a[static_cast<int>(TileEdge::South)], c[static_cast<int>(TileEdge::North)]);
  EXPECT_NE(a[static_cast<int>(TileEdge::East)], a[static_cast<int>(TileEdge::West)]);

  // The east neighbour made from its parent's surface instead: its west edge interpolates every
  // other vertex, so the heights (and hashes) differ, and both tiles hang a skirt there.
  const HeightBlock parent = upsampledWorldBlock(east.parent(), kN);
  const EdgeHeightHashes up = edgeHeightHashes(upsampleBlock(parent, east, kWgs84));
  EXPECT_NE(a[static_cast<int>(TileEdge::East)], up[static_cast<int>(TileEdge::West)]);
  std::unordered_map<geo::TileId, EdgeHeightHashes> drawn{{tile, a}, {east, up}, {south, c}};
  const DrawnEdgeHashes hashesOf = [&drawn](const geo::TileId& t) -> const EdgeHeightHashes* {
    const auto found = drawn.find(t);
    return found == drawn.end() ? nullptr : &found->second;
  };
  EXPECT_EQ(mismatchedEdges(tile, a, hashesOf),
            SkirtEdgeMask{1} << static_cast<int>(TileEdge::East));
  EXPECT_EQ(mismatchedEdges(east, up, hashesOf),
            SkirtEdgeMask{1} << static_cast<int>(TileEdge::West));
  drawn[east] = b;
  EXPECT_EQ(mismatchedEdges(tile, a, hashesOf), 0u);
  // Not drawn is neededSkirtEdges' business, not this one's.
  EXPECT_EQ(mismatchedEdges({9, 50, 50}, a, hashesOf), 0u);
}

TEST(WatertightSeams, NegativeZeroHashesAsZero) {
  HeightBlock one{kN, std::vector<int16_t>(kN * kN, 0)};
  HeightBlock other = one;
  other.exactSurfaceMeters.assign(kN * kN, 0.0);
  HeightBlock negative = one;
  negative.exactSurfaceMeters.assign(kN * kN, -0.0);
  EXPECT_EQ(edgeHeightHashes(other), edgeHeightHashes(negative));
  EXPECT_EQ(edgeHeightHashes(one), edgeHeightHashes(other));
  EXPECT_EQ(edgeHeightHashes(HeightBlock{}), EdgeHeightHashes{});
}

}  // namespace
}  // namespace globe::terrain
