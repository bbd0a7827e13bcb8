// No background shows through the terrain between tiles, of one level (their shared edge vertices
// round differently through two tiles' float transforms) or of different levels (the finer edge
// has samples the coarser one interpolates): skirts cover both. Looking at a block of real tiles
// from many directions and heights, every pixel that looks at the block is terrain.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "geo/cartographic.hpp"
#include "geo/ecef.hpp"
#include "tests/render/render_test_support.hpp"

namespace globe::render::test {
namespace {

class TileSeams : public RenderTest {
 protected:
  // Views from `heightMeters` above (lon, lat), looking at the ground point `aheadMeters` away
  // along `headingDegrees`, so the whole image lies inside the tile block.
  terrain::RenderView viewOver(double lonDegrees, double latDegrees, double heightMeters,
                               double headingDegrees, double aheadMeters) const {
    const LocalFrame frame = localFrame(lonDegrees, latDegrees);
    const double heading = geo::degreesToRadians(headingDegrees);
    const glm::dvec3 along = std::cos(heading) * frame.north + std::sin(heading) * frame.east;
    const glm::dvec3 ground = geo::cartographicToEcef(
        kWgs84, {geo::degreesToRadians(lonDegrees), geo::degreesToRadians(latDegrees), 0.0});
    const glm::dvec3 eye = ground + heightMeters * frame.up;
    const glm::dvec3 target = ground + aheadMeters * along;
    const glm::dvec3 sun = glm::normalize(frame.up + frame.east);
    return terrain::makeLookAtView(eye, target, frame.up, geo::degreesToRadians(40.0), kWidth,
                                   kHeight, sun);
  }

  // Counts background (space-black) pixels; the views below see only the tile block.
  static int backgroundPixels(const Image& image) {
    return image.width * image.height - image.countNonBackground();
  }
};

TEST_F(TileSeams, OneLevelShowsNoGapsFromAnyDirection) {
  // ~10 × 8 level-13 tiles (~2 km) on Fuji's eastern flanks.
  const auto tiles = loadTiles(13, 138.67, 35.25, 138.89, 35.41);
  ASSERT_GE(tiles.size(), 40u);
  upload(tiles);
  const std::vector<geo::TileId> ids = idsOf(tiles);
  int views = 0;
  for (double heading = 0.0; heading < 360.0; heading += 45.0) {
    for (const double height : {5000.0, 6500.0, 8000.0}) {
      const terrain::RenderView view = viewOver(138.78, 35.33, height, heading, 1500.0);
      FrameStats stats;
      const Image image = drawAndRead(view, ids, &stats);
      EXPECT_EQ(backgroundPixels(image), 0) << "heading " << heading << " height " << height;
      ++views;
      if (heading == 45.0 && height == 5000.0) savePng(image, "tile_seams_one_level");
    }
  }
  EXPECT_EQ(views, 24);
}

TEST_F(TileSeams, MixedLevelsShowNoGaps) {
  // Level 11 all around, the middle replaced by its level-12 and level-13 descendants.
  auto coarse = loadTiles(11, 138.62, 35.26, 138.84, 35.44);
  const auto middle = loadTiles(12, 138.70, 35.32, 138.76, 35.38);
  const auto finest = loadTiles(13, 138.72, 35.34, 138.74, 35.36);
  ASSERT_FALSE(middle.empty());
  ASSERT_FALSE(finest.empty());
  auto covered = [](const geo::TileId& tile, const std::vector<LoadedTile>& finer) {
    for (const LoadedTile& f : finer) {
      geo::TileId up = f.id;
      while (up.level > tile.level) up = up.parent();
      if (up == tile) return true;
    }
    return false;
  };
  // Keep whole families: a coarse tile is replaced by all four children or not at all.
  std::vector<LoadedTile> drawn;
  std::vector<geo::TileId> replaced11, replaced12;
  for (const LoadedTile& t : coarse) {
    if (covered(t.id, middle))
      replaced11.push_back(t.id);
    else
      drawn.push_back(t);
  }
  const auto level12 = loadTiles(12, 138.62, 35.26, 138.84, 35.44);
  for (const LoadedTile& t : level12) {
    geo::TileId parent = t.id.parent();
    if (std::find(replaced11.begin(), replaced11.end(), parent) == replaced11.end()) continue;
    if (covered(t.id, finest))
      replaced12.push_back(t.id);
    else
      drawn.push_back(t);
  }
  const auto level13 = loadTiles(13, 138.62, 35.26, 138.84, 35.44);
  for (const LoadedTile& t : level13) {
    if (std::find(replaced12.begin(), replaced12.end(), t.id.parent()) != replaced12.end()) {
      drawn.push_back(t);
    }
  }
  ASSERT_FALSE(replaced11.empty());
  ASSERT_FALSE(replaced12.empty());
  upload(drawn);
  const std::vector<geo::TileId> ids = idsOf(drawn);
  for (double heading = 0.0; heading < 360.0; heading += 45.0) {
    for (const double height : {5000.0, 8000.0}) {
      const terrain::RenderView view = viewOver(138.73, 35.35, height, heading, 1200.0);
      const Image image = drawAndRead(view, ids);
      EXPECT_EQ(backgroundPixels(image), 0) << "heading " << heading << " height " << height;
      if (heading == 90.0 && height == 5000.0) savePng(image, "tile_seams_mixed_levels");
    }
  }
}

}  // namespace
}  // namespace globe::render::test
