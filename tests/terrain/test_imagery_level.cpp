// The imagery level for a terrain tile (CesiumJS's texel-fits-the-error rule) and the uv
// transform into an ancestor's texture, checked against the tile rectangles themselves.
#include <gtest/gtest.h>

#include <cmath>

#include "geo/tiling_scheme.hpp"
#include "terrain/imagery_level.hpp"
#include "terrain/screen_space_error.hpp"

namespace globe::terrain {
namespace {

TEST(ImageryLevel, TheTexelFitsTheErrorOverTheMaximumScreenSpaceError) {
  const geo::Ellipsoid wgs84 = geo::ellipsoidFor(geo::GlobeModel::Wgs84);
  for (uint32_t vertices : {9u, 17u, 33u, 65u}) {
    for (double sse : {1.0, 2.0, 4.0}) {
      for (uint32_t level = 8; level < 20; ++level) {
        const uint32_t k = imageryLevelFor(level, vertices, 256, sse, 30);
        const double texel = [&](uint32_t l) {
          return wgs84.semiMajorAxisMeters * M_PI / std::ldexp(1.0, static_cast<int>(l)) / 256;
        }(k);
        const double allowed = geometricErrorMeters(level, vertices, wgs84) / sse;
        if (k < level) {
          EXPECT_LE(texel, allowed * (1 + 1e-12)) << level << " " << vertices << " " << sse;
          if (k > 0) {
            EXPECT_GT(texel * 2, allowed) << "not the coarsest level that fits";
          }
        }
      }
    }
  }
  EXPECT_EQ(imageryLevelFor(12, 17, 256, 2.0, 30), 11u);  // the default viewer
}

TEST(ImageryLevel, ClampedToTheTerrainLevelAndTheLayersDeepestLevel) {
  EXPECT_EQ(imageryLevelFor(0, 17, 256, 2.0, 30), 0u);
  EXPECT_EQ(imageryLevelFor(3, 65, 256, 2.0, 30), 3u);  // would be deeper: one tile per tile
  EXPECT_EQ(imageryLevelFor(15, 17, 256, 2.0, 9), 9u);
  EXPECT_EQ(imageryLevelFor(15, 17, 256, std::nan(""), 30), 14u);  // NaN counts as 2 px
}

TEST(ImageryLevel, TheUvTransformPutsTheTileWhereItLiesInItsAncestor) {
  const geo::TileId tile{14, 29001, 3187};
  for (uint32_t level = 0; level <= 14; ++level) {
    const geo::TileId ancestor = ancestorAt(tile, level);
    EXPECT_EQ(ancestorAt(tile, 14), tile);
    const auto t = geo::GeographicTilingScheme::tileRectangle(tile);
    const auto a = geo::GeographicTilingScheme::tileRectangle(ancestor);
    ASSERT_LE(a.westRadians, t.westRadians);
    ASSERT_GE(a.northRadians, t.northRadians);
    const glm::vec4 uv = uvTransformInAncestor(tile, ancestor);
    EXPECT_NEAR(uv.x, (t.westRadians - a.westRadians) / a.widthRadians(), 1e-7);
    EXPECT_NEAR(uv.y, (a.northRadians - t.northRadians) / a.heightRadians(), 1e-7);
    EXPECT_NEAR(uv.z, t.widthRadians() / a.widthRadians(), 1e-9);
    EXPECT_NEAR(uv.w, t.heightRadians() / a.heightRadians(), 1e-9);
  }
  EXPECT_EQ(uvTransformInAncestor(tile, tile), glm::vec4(0, 0, 1, 1));
}

// Edge-sampled textures: the tile's edges land on the first and last texels' centres, so both
// neighbours draw their shared edge from their (identical) edge samples.
TEST(ImageryLevel, EdgeSampledTransformPutsTheEdgesOnTheEdgeTexelsCentres) {
  const glm::vec4 whole = edgeSampledTransform({0.0f, 0.0f, 1.0f, 1.0f}, 256);
  EXPECT_FLOAT_EQ(whole.x, 0.5f / 256.0f);
  EXPECT_FLOAT_EQ(whole.x + whole.z, 255.5f / 256.0f);
  const geo::TileId tile{7, 13, 5}, ancestor{4, 1, 0};
  const glm::vec4 inside = edgeSampledTransform(uvTransformInAncestor(tile, ancestor), 256);
  const glm::vec4 plain = uvTransformInAncestor(tile, ancestor);
  // The same place of the ancestor, on the grid of its 255 intervals.
  EXPECT_FLOAT_EQ((inside.x - 0.5f / 256.0f) / (255.0f / 256.0f), plain.x);
  EXPECT_FLOAT_EQ(inside.z, plain.z * 255.0f / 256.0f);
}

}  // namespace
}  // namespace globe::terrain
