// Meshes of real tiles from the bundled pyramid: neighbours share their edges exactly, poles
// collapse, normals are sane, and mixed levels show no cracks thanks to the skirts.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"
#include "tests/render/render_test_support.hpp"

namespace globe::render::test {
namespace {

using terrain::gridVertexIndex;

glm::dvec3 reconstructed(const terrain::TileMesh& mesh, uint32_t vertex) {
  const float* v = &mesh.vertices[size_t{vertex} * terrain::kTileVertexFloats];
  return mesh.centerEcefMeters + glm::dvec3(v[0], v[1], v[2]);
}

TEST(RealMeshes, NeighboursShareEdgesExactlyAndFloatsAreCentimetreExact) {
  const auto tiles = loadTiles(12, 138.6, 35.25, 138.85, 35.45);
  ASSERT_GT(tiles.size(), 20u);
  std::map<geo::TileId, const LoadedTile*> byId;
  for (const LoadedTile& tile : tiles) byId[tile.id] = &tile;
  int sharedEdges = 0;
  for (const LoadedTile& tile : tiles) {
    const uint32_t n = tile.block.verticesPerSide;
    const terrain::BlockGrid grid{tile.id, n};
    const terrain::TileMesh mesh = terrain::buildTileMesh(tile.id, tile.block, kWgs84, 150.0);
    for (uint32_t i = 0; i < n; ++i) {
      for (uint32_t j = 0; j < n; ++j) {
        const glm::dvec3 exact = terrain::drawnVertexEcefMeters(
            kWgs84, grid, i, j, tile.block.surfaceHeightMetersAt(i, j));
        EXPECT_LT(glm::length(reconstructed(mesh, gridVertexIndex(i, j, n)) - exact), 0.01);
      }
    }
    const auto east = byId.find({tile.id.level, tile.id.x + 1, tile.id.y});
    if (east == byId.end()) continue;
    ++sharedEdges;
    const terrain::BlockGrid eastGrid{east->first, n};
    for (uint32_t k = 0; k < n; ++k) {
      ASSERT_EQ(tile.block.at(k, n - 1), east->second->block.at(k, 0));
      EXPECT_EQ(terrain::tileVertexEcefMeters(kWgs84, grid, k, n - 1,
                                              tile.block.surfaceHeightMetersAt(k, n - 1)),
                terrain::tileVertexEcefMeters(kWgs84, eastGrid, k, 0,
                                              east->second->block.surfaceHeightMetersAt(k, 0)));
    }
  }
  EXPECT_GT(sharedEdges, 10);
}

TEST(RealMeshes, PolesCollapseAndNormalsAreSaneOnTheWholeGlobe) {
  for (uint32_t level = 0; level <= 3; ++level) {
    const auto tiles = loadTiles(level, -180, -90, 180, 90);
    ASSERT_EQ(tiles.size(), 2u << (2 * level));
    for (const LoadedTile& tile : tiles) {
      const uint32_t n = tile.block.verticesPerSide;
      const terrain::TileMesh mesh = terrain::buildTileMesh(
          tile.id, tile.block, kWgs84, terrain::recommendedSkirtDepthMeters(level, n, kWgs84));
      for (uint32_t v = 0; v < mesh.vertexCount(); ++v) {
        const float* normal = &mesh.vertices[size_t{v} * terrain::kTileVertexFloats +
                                             terrain::kTileVertexNormalOffset];
        const glm::dvec3 nrm(normal[0], normal[1], normal[2]);
        ASSERT_TRUE(std::isfinite(nrm.x) && std::isfinite(nrm.y) && std::isfinite(nrm.z));
        EXPECT_NEAR(glm::length(nrm), 1.0, 1e-5);
        EXPECT_GT(glm::dot(nrm, geo::geodeticSurfaceNormal(kWgs84, reconstructed(mesh, v))), 0.0);
      }
      const bool north = tile.id.y == 0;
      const bool south = tile.id.y + 1 == geo::GeographicTilingScheme::tilesY(level);
      if (!north && !south) continue;
      const uint32_t row = north ? 0 : n - 1;
      for (uint32_t j = 1; j < n; ++j) {
        EXPECT_EQ(reconstructed(mesh, gridVertexIndex(row, j, n)),
                  reconstructed(mesh, gridVertexIndex(row, 0, n)))
            << "level " << level << " tile x " << tile.id.x << " j " << j;
      }
    }
  }
}

// Level-12 tiles with every other one replaced by its four level-13 children: the skirts close
// the T-junction cracks, so a low oblique view over the mountain shows no background below the
// horizon.
class MixedLevels : public RenderTest {};

TEST_F(MixedLevels, SkirtsLeaveNoCracks) {
  const auto coarse = loadTiles(12, 138.6, 35.2, 138.9, 35.5);
  ASSERT_GT(coarse.size(), 30u);
  std::vector<LoadedTile> mixed;
  for (const LoadedTile& tile : coarse) {
    if ((tile.id.x + tile.id.y) % 2 == 0) {
      mixed.push_back(tile);
      continue;
    }
    const geo::GlobeRectangle rect = geo::GeographicTilingScheme::tileRectangle(tile.id);
    const double eps = 1e-9;
    auto children = loadTiles(13, geo::radiansToDegrees(rect.westRadians) + eps,
                              geo::radiansToDegrees(rect.southRadians) + eps,
                              geo::radiansToDegrees(rect.eastRadians) - eps,
                              geo::radiansToDegrees(rect.northRadians) - eps);
    ASSERT_EQ(children.size(), 4u);
    for (LoadedTile& child : children) mixed.push_back(std::move(child));
  }
  // From 6 km south-west of the summit, 3000 m up, looking at it.
  const glm::dvec3 summit =
      geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(138.7274, 35.3606, 3000.0));
  const glm::dvec3 eye =
      geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(138.66, 35.31, 3200.0));
  const LocalFrame frame = localFrame(138.66, 35.31);
  const terrain::RenderView view =
      terrain::makeLookAtView(eye, summit, frame.up, geo::degreesToRadians(60.0), kWidth, kHeight,
                              glm::normalize(frame.up - frame.east));
  // Background pixels below the first terrain pixel of their column (the sky is above).
  auto countCracks = [](const Image& image) {
    int cracks = 0;
    for (int x = 0; x < image.width; ++x) {
      int y = 0;
      while (y < image.height && image.isBackground(x, y)) ++y;
      for (; y < image.height; ++y) cracks += image.isBackground(x, y) ? 1 : 0;
    }
    return cracks;
  };

  upload(mixed);
  const Image image = drawAndRead(view, idsOf(mixed));
  savePng(image, "fuji_mixed_levels");
  EXPECT_EQ(countCracks(image), 0);
  EXPECT_GT(image.countNonBackground(), kWidth * kHeight * 2 / 5);

  // The same without skirts does crack: the test can see them.
  TerrainRendererOptions options;
  options.skirts = false;
  auto bare = TerrainRenderer::create(options);
  ASSERT_TRUE(bare.ok()) << bare.error();
  for (const LoadedTile& tile : mixed) {
    ASSERT_TRUE((*bare)
                    ->uploadTile(tile.id, terrain::buildTileMesh(tile.id, tile.block, kWgs84, 0.0))
                    .ok());
  }
  (*bare)->draw(view, idsOf(mixed));
  const Image cracked = readImage(kWidth, kHeight);
  savePng(cracked, "fuji_mixed_levels_without_skirts");
  EXPECT_GT(countCracks(cracked), 0);
  (*bare).reset();
}

}  // namespace
}  // namespace globe::render::test
