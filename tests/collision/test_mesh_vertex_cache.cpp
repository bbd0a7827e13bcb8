// The cached vertices are the mesh's, bit for bit (terrain::tileVertexEcefMeters), at every level,
// on the poles and at +-180 deg, on WGS84 and on a sphere, whether the cache hits or misses; and
// the nadir point and normal are cartographicToEcef's and geodeticSurfaceNormal's.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "collision/mesh_vertex_cache.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/tile_mesh.hpp"

namespace globe::collision {
namespace {

void expectSame(const glm::dvec3& a, const glm::dvec3& b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.z, b.z);
}

TEST(MeshVertexCache, VerticesAreTheMeshsBitForBit) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> height(-11000.0, 9000.0);
  int poles = 0;
  for (const geo::Ellipsoid& ellipsoid : {geo::Ellipsoid::wgs84(), geo::Ellipsoid::sphere()}) {
    for (int k = 0; k < 20000; ++k) {
      const uint32_t level = static_cast<uint32_t>(rng() % 21);
      const uint32_t n = (k % 3 == 0) ? 33 : 17;
      const uint32_t x = static_cast<uint32_t>(rng() % geo::GeographicTilingScheme::tilesX(level));
      // Polar rows and the antimeridian's columns on purpose, now and then.
      const uint32_t rows = geo::GeographicTilingScheme::tilesY(level);
      const uint32_t y =
          k % 7 == 0 ? (k % 14 == 0 ? 0 : rows - 1) : static_cast<uint32_t>(rng() % rows);
      const terrain::BlockGrid grid{{level, k % 11 == 0 ? 0 : x, y}, n};
      const uint32_t row =
          k % 5 == 0 ? (k % 10 == 0 ? 0 : n - 1) : static_cast<uint32_t>(rng() % n);
      const uint32_t column = static_cast<uint32_t>(rng() % n);
      const double h = k % 13 == 0 ? 0.0 : height(rng);
      poles += std::abs(grid.latitudeDegrees(row)) == 90.0;
      const glm::dvec3 expected = terrain::tileVertexEcefMeters(ellipsoid, grid, row, column, h);
      expectSame(cachedTileVertexEcefMeters(ellipsoid, grid, row, column, h), expected);
      expectSame(cachedTileVertexEcefMeters(ellipsoid, grid, row, column, h), expected);  // a hit
      if (::testing::Test::HasFailure()) {
        FAIL() << "level " << level << " tile " << grid.tile.x << "," << grid.tile.y << " row "
               << row << " column " << column;
      }
    }
  }
  EXPECT_GT(poles, 100);
}

// A whole block's vertices at once (the lattice sampler's): the mesh's, pole rows included.
TEST(MeshVertexCache, BlockVerticesAreTheMeshsBitForBit) {
  std::mt19937_64 rng(11);
  for (const geo::TileId tile : {geo::TileId{14, 29124, 3260}, geo::TileId{3, 0, 0},
                                 geo::TileId{5, 63, 31}, geo::TileId{0, 1, 0}}) {
    terrain::HeightBlock block;
    block.verticesPerSide = 17;
    for (int i = 0; i < 17 * 17; ++i) {
      block.heights.push_back(static_cast<int16_t>(static_cast<int>(rng() % 9000) - 1000));
    }
    block.heights[5] = terrain::kNoDataHeight;  // water: 0 m
    const terrain::BlockGrid grid{tile, 17};
    const auto ellipsoid = geo::Ellipsoid::wgs84();
    const std::vector<glm::dvec3> vertices = blockVertexEcefMeters(ellipsoid, grid, block);
    ASSERT_EQ(vertices.size(), size_t{17 * 17});
    for (uint32_t row = 0; row < 17; ++row) {
      for (uint32_t column = 0; column < 17; ++column) {
        expectSame(vertices[row * 17 + column],
                   terrain::tileVertexEcefMeters(ellipsoid, grid, row, column,
                                                 block.surfaceHeightMetersAt(row, column)));
      }
    }
  }
}

TEST(MeshVertexCache, NadirPointAndNormalAreTheGeodesyLibrarys) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> lon(-3.141592653589793, 3.141592653589793),
      lat(-1.5707963267948966, 1.5707963267948966);
  for (const geo::Ellipsoid& ellipsoid : {geo::Ellipsoid::wgs84(), geo::Ellipsoid::sphere()}) {
    for (int k = 0; k < 20000; ++k) {
      const geo::Cartographic at{lon(rng), k % 100 == 0 ? 1.5707963267948966 : lat(rng), 0.0};
      const SurfacePoint both =
          surfacePointAndNormal(ellipsoid, at.longitudeRadians, at.latitudeRadians);
      expectSame(both.pointEcefMeters, geo::cartographicToEcef(ellipsoid, at));
      expectSame(both.normal, geo::geodeticSurfaceNormal(ellipsoid, at));
      if (::testing::Test::HasFailure()) FAIL() << at.longitudeRadians << " " << at.latitudeRadians;
    }
  }
}

}  // namespace
}  // namespace globe::collision
