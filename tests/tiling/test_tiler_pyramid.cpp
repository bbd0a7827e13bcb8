// The pyramid built from the bundled real data: every vertex, edge, parent/child and pole checked.
#include <gdal.h>
#include <gtest/gtest.h>

#include <numbers>

#include <map>

#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "geo/tiling_scheme.hpp"
#include "streaming/tile_store.hpp"
#include "terrain/block_grid.hpp"
#include "tests/support/bundled_pyramid_blocks.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "tiling/export_block.hpp"
#include "transport/atomic_file.hpp"

namespace globe::tiling {

using globe::testing::BundledPyramid;
namespace {

using globe::testing::bundledPyramid;

TEST_F(BundledPyramid, ManifestDescribesLevelsAndSources) {
  const formats::PyramidManifest& m = *manifest_;
  EXPECT_EQ(m.verticesPerSide, 17u);
  ASSERT_EQ(m.maxLevel(), 14u);  // 3″ Fuji: 180/(16·2^14) = 2.47″ ≤ 3″
  EXPECT_EQ(m.levels[0].tileCount, 2u);
  EXPECT_EQ(m.levels[6].tileCount, 128u * 64u);  // ETOPO20 (20′) reaches level 6 everywhere
  ASSERT_EQ(m.sources.size(), 3u);
  EXPECT_NE(m.sources[0].path.find("FUJI"), std::string::npos);  // finest first
  EXPECT_EQ(m.sources[0].finestLevel, 14u);
  EXPECT_EQ(m.sources[1].finestLevel, 11u);  // 30″ GTOPO30
  EXPECT_EQ(m.sources[2].finestLevel, 6u);
  EXPECT_LT(m.levels[0].heightRange.minimumMeters, -1000);  // sea floor
  EXPECT_LE(m.levels[14].heightRange.maximumMeters, 3742);  // Fuji's highest sample bounds it
  EXPECT_GT(m.levels[14].heightRange.maximumMeters, 3700);
  EXPECT_EQ(blocks_->size(), m.tileCount());
  // Deep levels exist only near the detailed inputs.
  for (const auto& [tile, data] : *blocks_) {
    if (tile.level <= 6) continue;
    const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
    const double w = rect.westRadians * 180 / std::numbers::pi,
                 e = rect.eastRadians * 180 / std::numbers::pi;
    const double tw = e - w;  // a sibling of a touching tile lies at most one tile away
    const bool nearFuji = e >= 138 - tw - 1e-3 && w <= 139 + tw + 1e-3;
    const bool nearEngland = e >= -2 - tw - 1e-3 && w <= tw + 1e-3;
    ASSERT_TRUE(nearFuji || nearEngland) << tile.level << "/" << tile.x << "/" << tile.y;
    if (tile.level > 11) {
      ASSERT_TRUE(nearFuji);
    }
  }
}

TEST_F(BundledPyramid, EveryVertexMatchesTheIndependentOracle) {
  const globe::testing::Oracle oracle(globe::testing::bundledInputs());
  uint64_t checked = 0, mismatches = 0;
  for (const auto& [tile, data] : *blocks_) {
    const terrain::BlockGrid grid{tile, n};
    for (uint32_t i = 0; i < n; ++i) {
      for (uint32_t j = 0; j < n; ++j) {
        const int16_t expected = oracle.height(grid.longitudeDegrees(j), grid.latitudeDegrees(i));
        const int16_t actual = data.second[i * n + j];
        ++checked;
        if (expected != actual && ++mismatches < 10) {
          ADD_FAILURE() << "tile " << tile.level << "/" << tile.x << "/" << tile.y << " vertex ("
                        << i << "," << j << "): " << actual << " != oracle " << expected;
        }
      }
    }
  }
  EXPECT_EQ(mismatches, 0u) << "of " << checked << " vertices";
  EXPECT_GT(checked, 1'000'000u);
}

TEST_F(BundledPyramid, SameLevelNeighboursShareTheirEdgesExactly) {
  uint64_t edges = 0;
  for (const auto& [tile, data] : *blocks_) {
    const uint32_t nx = geo::GeographicTilingScheme::tilesX(tile.level);
    // East neighbour, wrapping across the antimeridian.
    if (const auto* east = find({tile.level, (tile.x + 1) % nx, tile.y})) {
      for (uint32_t i = 0; i < n; ++i) ASSERT_EQ(data.second[i * n + n - 1], (*east)[i * n]);
      ++edges;
    }
    if (const auto* south = find({tile.level, tile.x, tile.y + 1})) {
      for (uint32_t j = 0; j < n; ++j) ASSERT_EQ(data.second[(n - 1) * n + j], (*south)[j]);
      ++edges;
    }
  }
  EXPECT_GT(edges, 20'000u);
  // The antimeridian seam is among them at every global level.
  for (uint32_t level = 0; level <= 6; ++level) {
    EXPECT_NE(find({level, geo::GeographicTilingScheme::tilesX(level) - 1, 0}), nullptr);
    EXPECT_NE(find({level, 0, 0}), nullptr);
  }
}

TEST_F(BundledPyramid, ParentsAreEveryOtherVertexOfTheirChildren) {
  uint64_t pairs = 0;
  const uint32_t half = (n - 1) / 2;
  for (const auto& [tile, data] : *blocks_) {
    if (tile.level == 0) continue;
    const auto* parent = find(tile.parent());
    ASSERT_NE(parent, nullptr) << "orphan " << tile.level << "/" << tile.x << "/" << tile.y;
    const uint32_t rowOffset = (tile.y % 2) * half, columnOffset = (tile.x % 2) * half;
    for (uint32_t i = 0; i <= half; ++i) {
      for (uint32_t j = 0; j <= half; ++j) {
        ASSERT_EQ(data.second[2 * i * n + 2 * j],
                  (*parent)[(rowOffset + i) * n + columnOffset + j]);
      }
    }
    ++pairs;
  }
  EXPECT_GT(pairs, 10'000u);
}

TEST_F(BundledPyramid, EachPoleIsOnePoint) {
  std::optional<int16_t> north, south;
  for (const auto& [tile, data] : *blocks_) {
    if (tile.y == 0) {
      for (uint32_t j = 0; j < n; ++j) {
        if (!north) north = data.second[j];
        ASSERT_EQ(data.second[j], *north);
      }
    }
    if (tile.y + 1 == geo::GeographicTilingScheme::tilesY(tile.level)) {
      for (uint32_t j = 0; j < n; ++j) {
        if (!south) south = data.second[(n - 1) * n + j];
        ASSERT_EQ(data.second[(n - 1) * n + j], *south);
      }
    }
  }
  ASSERT_TRUE(north && south);
  EXPECT_GT(*south, 1000);  // Antarctic plateau
}

TEST_F(BundledPyramid, RecordedHeightRangesBoundTheBlocks) {
  for (const auto& [tile, data] : *blocks_) {
    const formats::PackEntry& e = (*blocks_)[tile].first;
    const auto range = terrain::surfaceHeightRange({n, data.second});
    ASSERT_EQ(e.vertexRange.minimumMeters, range.minimumMeters);
    ASSERT_EQ(e.vertexRange.maximumMeters, range.maximumMeters);
    ASSERT_LE(e.subtreeRange.minimumMeters, e.vertexRange.minimumMeters);
    ASSERT_GE(e.subtreeRange.maximumMeters, e.vertexRange.maximumMeters);
    if (tile.level > 0) {
      const formats::PackEntry& parent = (*blocks_)[tile.parent()].first;
      ASSERT_LE(parent.subtreeRange.minimumMeters, e.subtreeRange.minimumMeters);
      ASSERT_GE(parent.subtreeRange.maximumMeters, e.subtreeRange.maximumMeters);
    }
  }
}

TEST_F(BundledPyramid, TileStoreLoadsABlockWithOneRead) {
  auto store = streaming::TileStore::open(bundledPyramid());
  ASSERT_TRUE(store) << store.error();
  uint64_t loads = 0;
  for (const auto& [tile, data] : *blocks_) {
    if (tile.level < 12) continue;
    auto block = (*store)->loadBlock(tile);
    ASSERT_TRUE(block) << block.error();
    ASSERT_EQ(block->heights, data.second);
    ++loads;
  }
  EXPECT_EQ((*store)->blockReads(), loads);
  // Each pack read once, and the first level-0 pack when the store opened.
  EXPECT_LE((*store)->packIndexReads(), manifest_->levels[12].packs.size() +
                                            manifest_->levels[13].packs.size() +
                                            manifest_->levels[14].packs.size() + 1);
  auto absent = (*store)->entry({14, 0, 0});
  ASSERT_TRUE(absent);
  EXPECT_FALSE(absent->has_value());
  auto missing = (*store)->loadBlock({14, 0, 0});
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("has no tile 14/0/0"), std::string::npos) << missing.error();
}

TEST_F(BundledPyramid, ExportedBlockOpensInGdalWithTheSameSamples) {
  // The tile over Fuji's summit (138.7275°E, 35.3606°N) at the finest level.
  const auto tile = geo::GeographicTilingScheme::positionToTile(
      138.7275 * std::numbers::pi / 180, 35.3606 * std::numbers::pi / 180, 14);
  ASSERT_TRUE(tile);
  const auto* data = find(*tile);
  ASSERT_NE(data, nullptr);
  const auto stem = globe::testing::freshTempDir("export") / "fuji_block";
  auto exported = exportBlock(bundledPyramid(), *tile, stem);
  ASSERT_TRUE(exported) << exported.error();

  GDALAllRegister();
  GDALDatasetH ds = GDALOpen((stem.string() + ".DEM").c_str(), GA_ReadOnly);
  ASSERT_NE(ds, nullptr);
  EXPECT_STREQ(GDALGetDriverShortName(GDALGetDatasetDriver(ds)), "EHdr");
  ASSERT_EQ(GDALGetRasterXSize(ds), 17);
  ASSERT_EQ(GDALGetRasterYSize(ds), 17);
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  EXPECT_EQ(GDALGetRasterDataType(band), GDT_Int16);
  std::vector<int16_t> samples(17 * 17);
  ASSERT_EQ(GDALRasterIO(band, GF_Read, 0, 0, 17, 17, samples.data(), 17, 17, GDT_Int16, 0, 0),
            CE_None);
  EXPECT_EQ(samples, *data);
  double transform[6];
  ASSERT_EQ(GDALGetGeoTransform(ds, transform), CE_None);
  const terrain::BlockGrid grid{*tile, 17};
  const double step = terrain::vertexSpacingDegrees(14, 17);
  EXPECT_NEAR(transform[0], grid.longitudeDegrees(0) - step / 2, 1e-9);
  EXPECT_NEAR(transform[3], grid.latitudeDegrees(0) + step / 2, 1e-9);
  EXPECT_NEAR(transform[1], step, 1e-12);
  GDALClose(ds);
  EXPECT_GT(*std::max_element(data->begin(), data->end()), 3600);  // the summit is in it
}

}  // namespace
}  // namespace globe::tiling
