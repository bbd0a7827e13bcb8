// Tiles made from their parent's surface (terrain/upsampled_block.hpp) give collision the parent's
// exact surface: at random points of every child, two generations deep, the exact height (the
// Oriented Ray against the mesh) is the parent's but for the slivers where a ray meets an edge's
// other triangle: under 1 m on level-5 cells (39 km, slopes to 40 %), under 1 mm at level 11; the
// means of the edges' ends (a height field's interpolation) miss it by the chords' sag, ~50 m.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "collision/exact_surface.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/rendering_tile_array.hpp"
#include "terrain/upsampled_block.hpp"
#include "tests/support/test_constants.hpp"
#include "tests/terrain/upsampled_test_world.hpp"

namespace globe::collision {
namespace {

using globe::test::kN;
using globe::test::kWgs84;

struct Gap {
  double exactMeters = 0;  // largest |child - parent| of the exact surface
  double meanMeters = 0;   // largest |mean of an edge's ends - the parent's exact surface there|
};

Gap compare(const geo::TileId& parentTile) {
  const terrain::HeightBlock parent = globe::testing::upsampledWorldBlock(parentTile, kN);
  const terrain::ArrayTile parentArray = terrain::makeArrayTile(parentTile, parent);
  std::mt19937_64 random(parentTile.level * 1000003u + parentTile.x);
  Gap gap;
  for (const geo::TileId& child : parentTile.children()) {
    const terrain::HeightBlock up = terrain::upsampleBlock(parent, child, kWgs84);
    for (const geo::TileId& grandchild : child.children()) {
      const terrain::HeightBlock upUp = terrain::upsampleBlock(up, grandchild, kWgs84);
      for (const auto& [tile, block] : {std::pair{child, &up}, std::pair{grandchild, &upUp}}) {
        const terrain::ArrayTile array = terrain::makeArrayTile(tile, *block);
        const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (int k = 0; k < 400; ++k) {
          const double lon = rect.westRadians + u(random) * rect.widthRadians();
          const double lat = rect.southRadians + u(random) * rect.heightRadians();
          const SurfaceSample a = exactTileSurfaceHeight(parentArray, kWgs84, lon, lat);
          const SurfaceSample b = exactTileSurfaceHeight(array, kWgs84, lon, lat);
          EXPECT_NE(b.triangle, SurfaceTriangle::None);
          gap.exactMeters = std::max(gap.exactMeters, std::abs(a.heightMeters - b.heightMeters));
        }
      }
    }
    // The child's vertex halfway along each parent cell's diagonal, against the mean of its ends.
    for (uint32_t i = 1; i < kN; i += 2) {
      for (uint32_t j = 1; j < kN; j += 2) {
        const double mean =
            0.5 * (up.surfaceHeightMetersAt(i - 1, j - 1) + up.surfaceHeightMetersAt(i + 1, j + 1));
        gap.meanMeters = std::max(gap.meanMeters, std::abs(mean - up.surfaceHeightMetersAt(i, j)));
      }
    }
  }
  return gap;
}

TEST(UpsampledSurface, CollisionReadsTheParentsSurface) {
  const Gap coarse = compare({5, 40, 9});
  EXPECT_LT(coarse.exactMeters, 1.0) << "the children's exact surface is the parent's";
  EXPECT_GT(coarse.meanMeters, 20.0) << "the means of the ends miss the chords' sag";
  const Gap fine = compare({11, 2600, 600});
  EXPECT_LT(fine.exactMeters, 0.001);
  RecordProperty("level5_exact_gap_m", std::to_string(coarse.exactMeters));
  RecordProperty("level5_mean_gap_m", std::to_string(coarse.meanMeters));
  std::printf("level 5: exact surface within %.4f m (means of ends: %.2f m); level 11: %.6f m\n",
              coarse.exactMeters, coarse.meanMeters, fine.exactMeters);
}

}  // namespace
}  // namespace globe::collision
