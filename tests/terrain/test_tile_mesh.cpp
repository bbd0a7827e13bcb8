// Tile mesh building: float offsets vs double ECEF, skirts, shared edges, poles, normals, and the
// shared index buffer with its documented diagonal.
#include "terrain/tile_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::terrain {
namespace {

using globe::test::kN;
using globe::test::kWgs84;

// A smooth synthetic world as a function of the exact vertex position, so that neighbouring tiles
// agree on their shared vertices like tiler output does: hills up to ~4.5 km, sea (no data) and
// negative land where the function is low. Constant along the pole rows (as the tiler makes them).
int16_t syntheticHeight(double longitudeDegrees, double latitudeDegrees) {
  if (std::abs(latitudeDegrees) == 90.0) return 2800;
  const double lon = geo::degreesToRadians(longitudeDegrees);
  const double lat = geo::degreesToRadians(latitudeDegrees);
  const double h = 1500.0 + 2000.0 * std::sin(3.0 * lon + 1.0) * std::cos(5.0 * lat) +
                   1000.0 * std::sin(40.0 * lon) * std::sin(37.0 * lat);
  if (h < -1200.0) return kNoDataHeight;
  return static_cast<int16_t>(std::lround(h));
}

HeightBlock syntheticBlock(const geo::TileId& tile) {
  const BlockGrid grid{tile, kN};
  HeightBlock block{kN, std::vector<int16_t>(kN * kN)};
  for (uint32_t i = 0; i < kN; ++i) {
    for (uint32_t j = 0; j < kN; ++j) {
      block.heights[i * kN + j] =
          syntheticHeight(grid.longitudeDegrees(j), grid.latitudeDegrees(i));
    }
  }
  return block;
}

glm::dvec3 reconstructed(const TileMesh& mesh, uint32_t vertex) {
  const float* v = &mesh.vertices[size_t{vertex} * kTileVertexFloats + kTileVertexPositionOffset];
  return mesh.centerEcefMeters + glm::dvec3(v[0], v[1], v[2]);
}

glm::dvec3 normalOf(const TileMesh& mesh, uint32_t vertex) {
  const float* v = &mesh.vertices[size_t{vertex} * kTileVertexFloats + kTileVertexNormalOffset];
  return glm::dvec3(v[0], v[1], v[2]);
}

float attribute(const TileMesh& mesh, uint32_t vertex, uint32_t offset) {
  return mesh.vertices[size_t{vertex} * kTileVertexFloats + offset];
}

// A spread of tiles: every level from 0 to 16, polar rows, both hemispheres, the antimeridian.
std::vector<geo::TileId> sampleTiles() {
  std::vector<geo::TileId> tiles;
  for (uint32_t level = 0; level <= 16; ++level) {
    const uint32_t nx = geo::GeographicTilingScheme::tilesX(level);
    const uint32_t ny = geo::GeographicTilingScheme::tilesY(level);
    for (const auto& [x, y] : std::array<std::pair<uint32_t, uint32_t>, 5>{
             {{0, 0}, {nx - 1, ny - 1}, {nx / 2, ny / 2}, {nx / 3, ny / 4}, {nx - 1, 0}}}) {
      tiles.push_back({level, x, y});
    }
  }
  return tiles;
}

double tileExtentMeters(const geo::TileId& tile) {
  return geo::GeographicTilingScheme::tileRectangle(tile).heightRadians() *
         kWgs84.semiMajorAxisMeters;
}

TEST(TileMesh, LayoutAndCounts) {
  const geo::TileId tile{5, 10, 7};
  const TileMesh mesh = buildTileMesh(tile, syntheticBlock(tile), kWgs84, 100.0);
  EXPECT_EQ(mesh.verticesPerSide, kN);
  EXPECT_TRUE(mesh.hasSkirts);
  EXPECT_EQ(mesh.vertexCount(), kN * kN + 4 * kN);
  EXPECT_EQ(mesh.vertices.size(), size_t{mesh.vertexCount()} * kTileVertexFloats);
  const TileMesh flat = buildTileMesh(tile, syntheticBlock(tile), kWgs84, 0.0);
  EXPECT_FALSE(flat.hasSkirts);
  EXPECT_EQ(flat.vertexCount(), kN * kN);
}

TEST(TileMesh, InvalidBlockGivesEmptyMesh) {
  HeightBlock wrongSize{16, std::vector<int16_t>(16 * 16, 0)};
  EXPECT_TRUE(buildTileMesh({3, 1, 1}, wrongSize, kWgs84, 10.0).vertices.empty());
  HeightBlock shortArray{kN, std::vector<int16_t>(10, 0)};
  EXPECT_TRUE(buildTileMesh({3, 1, 1}, shortArray, kWgs84, 10.0).vertices.empty());
}

TEST(TileMesh, FloatOffsetsReconstructDoublePositions) {
  for (const geo::TileId& tile : sampleTiles()) {
    const HeightBlock block = syntheticBlock(tile);
    const TileMesh mesh = buildTileMesh(tile, block, kWgs84, 0.0);
    const BlockGrid grid{tile, kN};
    double worst = 0.0;
    for (uint32_t i = 0; i < kN; ++i) {
      for (uint32_t j = 0; j < kN; ++j) {
        const glm::dvec3 exact =
            drawnVertexEcefMeters(kWgs84, grid, i, j, block.surfaceHeightMetersAt(i, j));
        worst =
            std::max(worst, glm::length(reconstructed(mesh, gridVertexIndex(i, j, kN)) - exact));
      }
    }
    // Float rounding of offsets up to half the tile: < 2^-24 of the extent, per component.
    EXPECT_LE(worst, 1.5e-7 * tileExtentMeters(tile) + 1e-6)
        << "tile " << tile.level << "/" << tile.x << "/" << tile.y;
    if (tile.level >= 8) {
      EXPECT_LT(worst, 0.01) << "tile " << tile.level << "/" << tile.x << "/" << tile.y;
    }
  }
}

TEST(TileMesh, PositionsMatchCartographicToEcef) {
  const geo::TileId tile{12, 3300, 1100};
  const HeightBlock block = syntheticBlock(tile);
  const TileMesh mesh = buildTileMesh(tile, block, kWgs84, 0.0);
  const BlockGrid grid{tile, kN};
  // Interior vertices (the edges too, but these steps do not reach them).
  for (uint32_t i = 4; i + 1 < kN; i += 4) {
    for (uint32_t j = 4; j + 1 < kN; j += 4) {
      const glm::dvec3 expected = geo::cartographicToEcef(
          kWgs84, geo::Cartographic::fromDegrees(grid.longitudeDegrees(j), grid.latitudeDegrees(i),
                                                 block.surfaceHeightMetersAt(i, j)));
      EXPECT_LT(glm::length(reconstructed(mesh, gridVertexIndex(i, j, kN)) - expected), 0.01);
    }
  }
}

// Every vertex is drawn at its exact place rounded to the level's quantum (a power of two), so
// neighbours' shared vertices land on the same point; the pole stays on the axis.
TEST(TileMesh, DrawnVerticesLieOnTheLevelQuantum) {
  for (const geo::TileId& tile :
       {geo::TileId{13, 9000, 3000}, geo::TileId{4, 3, 0}, geo::TileId{20, 1048575, 0},
        geo::TileId{0, 1, 0}}) {
    const TileMesh mesh = buildTileMesh(tile, syntheticBlock(tile), kWgs84, 50.0);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(std::fmod(mesh.centerEcefMeters[c], originQuantumMeters(tile.level)), 0.0);
    }
    const BlockGrid grid{tile, kN};
    const double quantum = vertexQuantumMeters(tile.level);
    EXPECT_EQ(quantum, std::ldexp(1.0, -static_cast<int>(tile.level)));
    for (uint32_t i = 0; i < kN; ++i) {
      for (uint32_t j = 0; j < kN; ++j) {
        const glm::dvec3 exact = tileVertexEcefMeters(kWgs84, grid, i, j, 100.0);
        const glm::dvec3 drawn = drawnVertexEcefMeters(kWgs84, grid, i, j, 100.0);
        for (int c = 0; c < 3; ++c) {
          EXPECT_LE(std::abs(drawn[c] - exact[c]), 0.5 * quantum) << i << "," << j;
          EXPECT_EQ(std::fmod(drawn[c], quantum), 0.0) << i << "," << j;
        }
        if (std::abs(grid.latitudeDegrees(i)) == 90.0) {
          EXPECT_EQ(drawn.x, 0.0) << "the pole stays on the axis";
          EXPECT_EQ(drawn.y, 0.0) << "the pole stays on the axis";
        }
      }
    }
  }
}

// Where buildTileMesh puts interior vertex (row, column): its height along the normal.
double drawnHeightMeters(const TileMesh& mesh, uint32_t row, uint32_t column) {
  return geo::ecefToCartographic(kWgs84, reconstructed(mesh, gridVertexIndex(row, column, kN)))
      ->heightMeters;
}

// One tile mixing every kind of sample: water over a known floor (band-coded), water of unknown
// depth (-9999), land below sea level, land, and the samples next to the codes' boundaries.
struct SampleCase {
  uint32_t row, column;
  int16_t sample;
  bool water;
  double waterSurfaceMeters;  // drawn height by default
  double seaFloorMeters;      // drawn height with SeaSurface::SeaFloor
  double colourMeters;        // the height attribute either way
};
const SampleCase kMixedCases[] = {
    {2, 2, 250, false, 250, 250, 250},
    {2, 5, kNoDataHeight, true, 0, 0, 0},
    {2, 8, encodeWater(-200), true, 0, -200, -200},
    {5, 2, -400, false, -400, -400, -400},  // the Dead Sea is land
    {5, 5, -35, false, -35, -35, -35},
    {5, 8, -9998, false, -9998, -9998, -9998},
    {8, 2, -10000, false, -10000, -10000, -10000},
    {8, 5, -20000, false, -20000, -20000, -20000},  // the band's edge: not water
    {8, 8, -20001, true, 0, -1, -1},                // the shallowest floor encodable
    {11, 2, encodeWater(kDeepestSeaFloorMeters), true, 0, -12767, -12767},
    {11, 5, encodeWater(-0.4), true, 0, 0, 0},  // a floor at 0 m is depth unknown
    {11, 8, -1, false, -1, -1, -1},
};

HeightBlock mixedBlock(SeaSurface sea) {
  HeightBlock block{kN, std::vector<int16_t>(kN * kN, 250), sea};
  for (const SampleCase& c : kMixedCases)
    block.heights[gridVertexIndex(c.row, c.column, kN)] = c.sample;
  return block;
}

TEST(TileMesh, WaterIsDrawnAtSeaLevelByDefaultAndLandBelowSeaLevelIsLand) {
  const geo::TileId tile{9, 300, 100};
  const TileMesh mesh = buildTileMesh(tile, mixedBlock(SeaSurface::Water), kWgs84, 0.0);
  for (const SampleCase& c : kMixedCases) {
    SCOPED_TRACE(::testing::Message() << "sample " << c.sample);
    const uint32_t v = gridVertexIndex(c.row, c.column, kN);
    EXPECT_EQ(isWater(c.sample), c.water);
    EXPECT_NEAR(drawnHeightMeters(mesh, c.row, c.column), c.waterSurfaceMeters, 0.01);
    EXPECT_EQ(attribute(mesh, v, kTileVertexSeaOffset), c.water ? 1.0f : 0.0f);
    EXPECT_EQ(attribute(mesh, v, kTileVertexHeightOffset), static_cast<float>(c.colourMeters));
  }
}

TEST(TileMesh, WithTheSeaFloorWaterIsDrawnAtItsFloorAndKeepsItsSeaFlag) {
  const geo::TileId tile{9, 300, 100};
  const TileMesh mesh = buildTileMesh(tile, mixedBlock(SeaSurface::SeaFloor), kWgs84, 0.0);
  for (const SampleCase& c : kMixedCases) {
    SCOPED_TRACE(::testing::Message() << "sample " << c.sample);
    const uint32_t v = gridVertexIndex(c.row, c.column, kN);
    EXPECT_NEAR(drawnHeightMeters(mesh, c.row, c.column), c.seaFloorMeters, 0.01);
    EXPECT_EQ(attribute(mesh, v, kTileVertexSeaOffset), c.water ? 1.0f : 0.0f);
    EXPECT_EQ(attribute(mesh, v, kTileVertexHeightOffset), static_cast<float>(c.colourMeters));
    // The mesh and collision read the same surface.
    EXPECT_EQ(mixedBlock(SeaSurface::SeaFloor).surfaceHeightMetersAt(c.row, c.column),
              c.seaFloorMeters);
  }
}

TEST(TileMesh, SkirtsHangBelowTheSurfaceTheBlockDraws) {
  const geo::TileId tile{9, 300, 100};
  for (const SeaSurface sea : {SeaSurface::Water, SeaSurface::SeaFloor}) {
    HeightBlock block{kN, std::vector<int16_t>(kN * kN, encodeWater(-3000)), sea};
    const TileMesh mesh = buildTileMesh(tile, block, kWgs84, 500.0);
    const double surface = sea == SeaSurface::Water ? 0.0 : -3000.0;
    const glm::dvec3 skirt = reconstructed(mesh, skirtVertexIndex(TileEdge::North, 8, kN));
    const glm::dvec3 top = reconstructed(mesh, gridVertexIndex(0, 8, kN));
    EXPECT_NEAR(geo::ecefToCartographic(kWgs84, top)->heightMeters, surface, 0.01);
    EXPECT_NEAR(geo::ecefToCartographic(kWgs84, skirt)->heightMeters, surface - 500.0, 0.01);
  }
}

TEST(TileMesh, UvIsTileLocal) {
  const geo::TileId tile{4, 5, 6};
  const TileMesh mesh = buildTileMesh(tile, syntheticBlock(tile), kWgs84, 10.0);
  for (uint32_t i = 0; i < kN; ++i) {
    for (uint32_t j = 0; j < kN; ++j) {
      const uint32_t v = gridVertexIndex(i, j, kN);
      EXPECT_EQ(attribute(mesh, v, kTileVertexUvOffset), static_cast<float>(j) / 16.0f);
      EXPECT_EQ(attribute(mesh, v, kTileVertexUvOffset + 1), static_cast<float>(i) / 16.0f);
    }
  }
}

TEST(TileMesh, SkirtsHangBelowEdgesByRequestedDepth) {
  for (const geo::TileId& tile : {geo::TileId{10, 1800, 300}, geo::TileId{14, 28000, 4000}}) {
    const double depth = recommendedSkirtDepthMeters(tile.level, kN, kWgs84);
    const TileMesh mesh = buildTileMesh(tile, syntheticBlock(tile), kWgs84, depth);
    const BlockGrid grid{tile, kN};
    for (uint32_t e = 0; e < 4; ++e) {
      const auto edge = static_cast<TileEdge>(e);
      for (uint32_t k = 0; k < kN; ++k) {
        const uint32_t row = edge == TileEdge::North ? 0 : edge == TileEdge::South ? kN - 1 : k;
        const uint32_t column = edge == TileEdge::West ? 0 : edge == TileEdge::East ? kN - 1 : k;
        const uint32_t top = gridVertexIndex(row, column, kN);
        const uint32_t skirt = skirtVertexIndex(edge, k, kN);
        const glm::dvec3 up = geo::geodeticSurfaceNormal(
            kWgs84, geo::Cartographic::fromDegrees(grid.longitudeDegrees(column),
                                                   grid.latitudeDegrees(row), 0.0));
        const glm::dvec3 drop = reconstructed(mesh, skirt) - reconstructed(mesh, top);
        EXPECT_LT(glm::length(drop + depth * up), 0.01) << "edge " << e << " k " << k;
        for (uint32_t f = kTileVertexNormalOffset; f < kTileVertexFloats; ++f) {
          EXPECT_EQ(attribute(mesh, skirt, f), attribute(mesh, top, f));
        }
      }
    }
  }
}

TEST(TileMesh, RecommendedSkirtDepth) {
  EXPECT_NEAR(recommendedSkirtDepthMeters(14, kN, kWgs84), 152.9, 0.5);
  EXPECT_NEAR(recommendedSkirtDepthMeters(6, kN, kWgs84), 9030.0, 10.0);
  for (uint32_t level = 1; level <= 20; ++level) {
    EXPECT_LT(recommendedSkirtDepthMeters(level, kN, kWgs84),
              recommendedSkirtDepthMeters(level - 1, kN, kWgs84));
  }
}

TEST(TileMesh, SharedEdgeVerticesCoincideExactlyInDouble) {
  for (const geo::TileId& tile : {geo::TileId{6, 40, 20}, geo::TileId{13, 9000, 3000}}) {
    const geo::TileId east{tile.level, tile.x + 1, tile.y};
    const geo::TileId south{tile.level, tile.x, tile.y + 1};
    const HeightBlock a = syntheticBlock(tile), b = syntheticBlock(east), c = syntheticBlock(south);
    const BlockGrid ga{tile, kN}, gb{east, kN}, gc{south, kN};
    const TileMesh ma = buildTileMesh(tile, a, kWgs84, 50.0);
    const TileMesh mb = buildTileMesh(east, b, kWgs84, 50.0);
    const TileMesh mc = buildTileMesh(south, c, kWgs84, 50.0);
    for (uint32_t k = 0; k < kN; ++k) {
      const glm::dvec3 pa =
          tileVertexEcefMeters(kWgs84, ga, k, kN - 1, a.surfaceHeightMetersAt(k, kN - 1));
      const glm::dvec3 pb = tileVertexEcefMeters(kWgs84, gb, k, 0, b.surfaceHeightMetersAt(k, 0));
      EXPECT_EQ(pa, pb) << "east edge k " << k;
      // Drawn, both put it at the same point, exactly: the mesh's centre plus its float offset.
      EXPECT_EQ(reconstructed(ma, gridVertexIndex(k, kN - 1, kN)),
                reconstructed(mb, gridVertexIndex(k, 0, kN)))
          << "east edge k " << k;
      const glm::dvec3 qa =
          tileVertexEcefMeters(kWgs84, ga, kN - 1, k, a.surfaceHeightMetersAt(kN - 1, k));
      const glm::dvec3 qc = tileVertexEcefMeters(kWgs84, gc, 0, k, c.surfaceHeightMetersAt(0, k));
      EXPECT_EQ(qa, qc) << "south edge k " << k;
      EXPECT_EQ(reconstructed(ma, gridVertexIndex(kN - 1, k, kN)),
                reconstructed(mc, gridVertexIndex(0, k, kN)))
          << "south edge k " << k;
      // The along-edge normal component agrees across the edge (it uses shared vertices only).
      const glm::dvec3 alongEdge =
          glm::normalize(tileVertexEcefMeters(kWgs84, ga, std::min(k + 1, kN - 1), kN - 1, 0.0) -
                         tileVertexEcefMeters(kWgs84, ga, k > 0 ? k - 1 : 0, kN - 1, 0.0));
      EXPECT_NEAR(glm::dot(normalOf(ma, gridVertexIndex(k, kN - 1, kN)), alongEdge),
                  glm::dot(normalOf(mb, gridVertexIndex(k, 0, kN)), alongEdge), 0.02);
    }
    // A parent's edge vertices are every other vertex of its children's.
    const geo::TileId parent = tile.parent();
    const BlockGrid gp{parent, kN};
    const auto children = parent.children();
    const BlockGrid nw{children[0], kN};
    for (uint32_t k = 0; k < kN; k += 2) {
      EXPECT_EQ(tileVertexEcefMeters(kWgs84, gp, 0, k / 2, 100.0),
                tileVertexEcefMeters(kWgs84, nw, 0, k, 100.0));
    }
  }
}

TEST(TileMesh, PoleVerticesCollapseWithSaneNormals) {
  for (uint32_t level : {0u, 1u, 3u, 9u}) {
    const uint32_t lastRow = geo::GeographicTilingScheme::tilesY(level) - 1;
    for (const geo::TileId& tile : {geo::TileId{level, 0, 0}, geo::TileId{level, 1, lastRow}}) {
      const TileMesh mesh = buildTileMesh(tile, syntheticBlock(tile), kWgs84, 500.0);
      const uint32_t poleRow = tile.y == 0 ? 0 : kN - 1;
      const double sign = tile.y == 0 ? 1.0 : -1.0;
      const glm::dvec3 first = reconstructed(mesh, gridVertexIndex(poleRow, 0, kN));
      EXPECT_LT(std::hypot(first.x, first.y), 1.5e-7 * tileExtentMeters(tile) + 1e-6);
      EXPECT_NEAR(first.z, sign * (kWgs84.semiMinorAxisMeters + 2800.0),
                  1.5e-7 * tileExtentMeters(tile) + 1e-6);
      for (uint32_t j = 0; j < kN; ++j) {
        const uint32_t v = gridVertexIndex(poleRow, j, kN);
        EXPECT_EQ(reconstructed(mesh, v), first) << "level " << level << " j " << j;
        const glm::dvec3 n = normalOf(mesh, v);
        EXPECT_NEAR(n.z, sign, 1e-12);
        const uint32_t skirt =
            skirtVertexIndex(tile.y == 0 ? TileEdge::North : TileEdge::South, j, kN);
        EXPECT_EQ(reconstructed(mesh, skirt),
                  reconstructed(mesh, skirtVertexIndex(
                                          tile.y == 0 ? TileEdge::North : TileEdge::South, 0, kN)));
      }
    }
  }
}

TEST(TileMesh, NormalsAreFiniteUnitAndUp) {
  for (const geo::TileId& tile : sampleTiles()) {
    const TileMesh mesh = buildTileMesh(tile, syntheticBlock(tile), kWgs84, 100.0);
    for (uint32_t v = 0; v < mesh.vertexCount(); ++v) {
      const glm::dvec3 n = normalOf(mesh, v);
      ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
      EXPECT_NEAR(glm::length(n), 1.0, 1e-6);
      const glm::dvec3 p = reconstructed(mesh, v);
      const glm::dvec3 up = geo::geodeticSurfaceNormal(kWgs84, p);
      EXPECT_GT(glm::dot(n, up), 0.0) << "tile " << tile.level << "/" << tile.x << "/" << tile.y;
    }
    for (float value : mesh.vertices) ASSERT_TRUE(std::isfinite(value));
  }
}

TEST(TileMesh, FlatGroundNormalsAreTheEllipsoidNormal) {
  const geo::TileId tile{10, 700, 300};
  const HeightBlock flat{kN, std::vector<int16_t>(kN * kN, 500)};
  const TileMesh mesh = buildTileMesh(tile, flat, kWgs84, 0.0);
  const BlockGrid grid{tile, kN};
  for (uint32_t i = 0; i < kN; ++i) {
    for (uint32_t j = 0; j < kN; ++j) {
      const glm::dvec3 up = geo::geodeticSurfaceNormal(
          kWgs84,
          geo::Cartographic::fromDegrees(grid.longitudeDegrees(j), grid.latitudeDegrees(i), 0));
      EXPECT_GT(glm::dot(normalOf(mesh, gridVertexIndex(i, j, kN)), up), std::cos(1e-3));
    }
  }
}

TEST(TileMesh, SlopeTiltsNormalDownhill) {
  // Heights rising eastwards by 100 m per vertex: the normal leans west.
  const geo::TileId tile{12, 6000, 1000};
  HeightBlock ramp{kN, std::vector<int16_t>(kN * kN)};
  for (uint32_t i = 0; i < kN; ++i) {
    for (uint32_t j = 0; j < kN; ++j) ramp.heights[i * kN + j] = static_cast<int16_t>(100 * j);
  }
  const TileMesh mesh = buildTileMesh(tile, ramp, kWgs84, 0.0);
  const BlockGrid grid{tile, kN};
  const double lon = geo::degreesToRadians(grid.longitudeDegrees(8));
  const glm::dvec3 east(-std::sin(lon), std::cos(lon), 0.0);
  const glm::dvec3 n = normalOf(mesh, gridVertexIndex(8, 8, kN));
  // Spacing at level 12 is ~611 m east-west at this latitude band; tan(tilt) = 100 / spacing.
  const double spacing = geo::degreesToRadians(vertexSpacingDegrees(12, kN)) *
                         kWgs84.semiMajorAxisMeters *
                         std::cos(geo::degreesToRadians(grid.latitudeDegrees(8)));
  EXPECT_NEAR(glm::dot(n, east), -std::sin(std::atan(100.0 / spacing)), 0.01);
}

// Index buffer: every quad is exactly two triangles split along (i, j)–(i+1, j+1).
TEST(GridIndices, EachQuadIsTwoTrianglesWithTheDocumentedDiagonal) {
  for (uint32_t n : {3u, 5u, 17u, 33u}) {
    const std::vector<uint32_t> indices = buildGridIndices(n, false);
    ASSERT_EQ(indices.size(), size_t{6} * (n - 1) * (n - 1));
    std::map<std::pair<uint32_t, uint32_t>, int> trianglesPerQuad;
    for (size_t t = 0; t < indices.size() / 3; ++t) {
      const std::array<uint32_t, 3> tri{indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]};
      uint32_t minRow = n, minColumn = n;
      for (uint32_t v : tri) {
        ASSERT_LT(v, n * n);
        minRow = std::min(minRow, v / n);
        minColumn = std::min(minColumn, v % n);
      }
      const uint32_t i = minRow, j = minColumn;
      ASSERT_LT(i + 1, n);
      ASSERT_LT(j + 1, n);
      ++trianglesPerQuad[{i, j}];
      // Triangle 2q is the south-west half, 2q+1 the north-east half, in this vertex order.
      const uint32_t q = i * (n - 1) + j;
      const uint32_t a = gridVertexIndex(i, j, n), b = gridVertexIndex(i, j + 1, n);
      const uint32_t c = gridVertexIndex(i + 1, j, n), d = gridVertexIndex(i + 1, j + 1, n);
      const std::array<uint32_t, 3> expected =
          (t == 2 * q) ? std::array<uint32_t, 3>{a, c, d} : std::array<uint32_t, 3>{a, d, b};
      ASSERT_TRUE(t == 2 * q || t == 2 * q + 1);
      EXPECT_EQ(tri, expected);
      // Both contain the diagonal (i, j)–(i+1, j+1) and neither contains (i, j+1)–(i+1, j).
      const std::set<uint32_t> set(tri.begin(), tri.end());
      EXPECT_TRUE(set.contains(a) && set.contains(d));
      EXPECT_FALSE(set.contains(b) && set.contains(c));
    }
    EXPECT_EQ(trianglesPerQuad.size(), size_t{n - 1} * (n - 1));
    for (const auto& [quad, count] : trianglesPerQuad) EXPECT_EQ(count, 2);
  }
}

TEST(GridIndices, SkirtsAddTwoTrianglesPerEdgeSegment) {
  const std::vector<uint32_t> plain = buildGridIndices(kN, false);
  const std::vector<uint32_t> skirted = buildGridIndices(kN, true);
  ASSERT_EQ(skirted.size(), plain.size() + size_t{4} * (kN - 1) * 6);
  EXPECT_TRUE(std::equal(plain.begin(), plain.end(), skirted.begin()));
  std::set<uint32_t> used(skirted.begin(), skirted.end());
  EXPECT_EQ(used.size(), size_t{tileVertexCount(kN, true)});
  EXPECT_EQ(*used.rbegin(), tileVertexCount(kN, true) - 1);
}

// Winding: grid triangles face up, skirt triangles face away from the tile (counter-clockwise
// from outside), so back-face culling keeps what can be seen.
TEST(GridIndices, TrianglesFaceOutwards) {
  const geo::TileId tile{11, 2000, 700};
  const TileMesh mesh = buildTileMesh(tile, syntheticBlock(tile), kWgs84, 300.0);
  const std::vector<uint32_t> indices = buildGridIndices(kN, true);
  const glm::dvec3 center = reconstructed(mesh, gridVertexIndex(kN / 2, kN / 2, kN));
  const glm::dvec3 up = geo::geodeticSurfaceNormal(kWgs84, center);
  const size_t gridTriangles = size_t{2} * (kN - 1) * (kN - 1);
  for (size_t t = 0; t < indices.size() / 3; ++t) {
    const glm::dvec3 p0 = reconstructed(mesh, indices[3 * t]);
    const glm::dvec3 p1 = reconstructed(mesh, indices[3 * t + 1]);
    const glm::dvec3 p2 = reconstructed(mesh, indices[3 * t + 2]);
    const glm::dvec3 normal = glm::cross(p1 - p0, p2 - p0);
    if (t < gridTriangles) {
      EXPECT_GT(glm::dot(normal, up), 0.0) << "grid triangle " << t;
    } else {
      const glm::dvec3 centroid = (p0 + p1 + p2) / 3.0;
      glm::dvec3 outward = centroid - center;
      outward -= glm::dot(outward, up) * up;
      EXPECT_GT(glm::dot(normal, outward), 0.0) << "skirt triangle " << t;
    }
  }
}

}  // namespace
}  // namespace globe::terrain
