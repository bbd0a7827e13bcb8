// The renderer's GPU tile cache: upload, replace, evict, residency counters, missing tiles, and
// the frame counters of draw().
#include <gtest/gtest.h>

#include "geo/cartographic.hpp"
#include "tests/render/render_test_support.hpp"

namespace globe::render::test {
namespace {

class TileCache : public RenderTest {};

TEST_F(TileCache, CountsBytesAndTilesAndSkipsMissingOnes) {
  const auto tiles = loadTiles(2, -180, -90, 180, 90);
  ASSERT_EQ(tiles.size(), 32u);
  const uint64_t baseBytes = renderer_->gpuBytesResident();
  // The shared index buffer: (2·16·16 + 4·16·2) triangles of 16-bit indices.
  EXPECT_EQ(renderer_->indicesPerTile(), 3u * (512u + 128u));
  EXPECT_EQ(baseBytes, 3u * 640u * 2u);
  const uint64_t tileBytes =
      uint64_t{terrain::tileVertexCount(17, true)} * terrain::kTileVertexFloats * sizeof(float);
  upload(tiles);
  EXPECT_EQ(renderer_->tilesResident(), 32u);
  EXPECT_EQ(renderer_->gpuBytesResident(), baseBytes + 32 * tileBytes);
  EXPECT_TRUE(renderer_->hasTile(tiles[5].id));

  // Replacing a tile does not count it twice.
  upload({tiles[5]});
  EXPECT_EQ(renderer_->tilesResident(), 32u);
  EXPECT_EQ(renderer_->gpuBytesResident(), baseBytes + 32 * tileBytes);

  EXPECT_TRUE(renderer_->evictTile(tiles[5].id));
  EXPECT_FALSE(renderer_->evictTile(tiles[5].id));
  EXPECT_FALSE(renderer_->hasTile(tiles[5].id));
  EXPECT_EQ(renderer_->gpuBytesResident(), baseBytes + 31 * tileBytes);

  const glm::dvec3 eye(3.0 * kWgs84.semiMajorAxisMeters, 0.0, 0.0);
  const terrain::RenderView view = terrain::makeLookAtView(
      eye, glm::dvec3(0.0), glm::dvec3(0, 0, 1), geo::degreesToRadians(45.0), kWidth, kHeight, eye);
  std::vector<geo::TileId> ids = idsOf(tiles);
  ids.push_back({20, 1, 1});  // never uploaded
  const FrameStats stats = renderer_->draw(view, ids);
  EXPECT_EQ(stats.tilesRequested, 33u);
  EXPECT_EQ(stats.tilesDrawn, 31u);
  EXPECT_EQ(stats.tilesMissing, 2u);
  EXPECT_EQ(stats.drawCalls, 31u);
  // 512 grid triangles a tile, plus 32 for each edge that gets a skirt: the 15 drawn tiles of
  // the polar rows on their pole edge (tiles[5], 2/5/0, is in the north row and not drawn),
  // and its three drawn neighbours on the edge facing it.
  ASSERT_EQ(tiles[5].id, (geo::TileId{2, 5, 0}));
  EXPECT_EQ(stats.triangles, 31u * 512u + (15u + 3u) * 32u);
  EXPECT_EQ(stats.tilesResident, 31u);
  EXPECT_EQ(stats.gpuBytesResident, baseBytes + 31 * tileBytes);

  renderer_->evictAllTiles();
  EXPECT_EQ(renderer_->tilesResident(), 0u);
  EXPECT_EQ(renderer_->gpuBytesResident(), baseBytes);
  const Image empty = drawAndRead(view, ids);
  EXPECT_EQ(empty.countNonBackground(), 0);
}

TEST_F(TileCache, RejectsMeshesOfTheWrongShape) {
  const auto tiles = loadTiles(0, -180, -90, 180, 90);
  ASSERT_EQ(tiles.size(), 2u);
  terrain::TileMesh mesh = terrain::buildTileMesh(tiles[0].id, tiles[0].block, kWgs84, 0.0);
  auto noSkirts = renderer_->uploadTile(tiles[0].id, mesh);
  ASSERT_FALSE(noSkirts.ok());
  EXPECT_NE(noSkirts.error().find("tile 0/0/0"), std::string::npos) << noSkirts.error();
  mesh = terrain::buildTileMesh(tiles[0].id, tiles[0].block, kWgs84, 1000.0);
  mesh.vertices.pop_back();
  EXPECT_FALSE(renderer_->uploadTile(tiles[0].id, mesh).ok());
  EXPECT_FALSE(renderer_->hasTile(tiles[0].id));
  EXPECT_EQ(renderer_->tilesResident(), 0u);
}

TEST_F(TileCache, ImageryIsCountedAndValidated) {
  const uint64_t before = renderer_->gpuBytesResident();
  std::vector<uint8_t> pixels(64 * 32 * 4, 200);
  EXPECT_FALSE(renderer_->setImagery(pixels, 64, 31).ok());
  EXPECT_FALSE(renderer_->hasImagery());
  ASSERT_TRUE(renderer_->setImagery(pixels, 64, 32).ok());
  EXPECT_TRUE(renderer_->hasImagery());
  EXPECT_GT(renderer_->gpuBytesResident(), before + pixels.size());
  renderer_->clearImagery();
  EXPECT_EQ(renderer_->gpuBytesResident(), before);
}

}  // namespace
}  // namespace globe::render::test
