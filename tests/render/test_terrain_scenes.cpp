// Real terrain close up: no-data sea in eastern England is blue, Mount Fuji's flanks light up
// with the sun, and a camera 1 m above the ground sees solid, stable terrain.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"
#include "tests/render/render_test_support.hpp"

namespace globe::render::test {
namespace {

// Surface position of grid vertex (row, column) of a loaded tile.
glm::dvec3 vertexPosition(const LoadedTile& tile, uint32_t row, uint32_t column) {
  const terrain::BlockGrid grid{tile.id, tile.block.verticesPerSide};
  return terrain::tileVertexEcefMeters(kWgs84, grid, row, column,
                                       tile.block.surfaceHeightMetersAt(row, column));
}

// Interior vertices whose whole 3×3 neighbourhood satisfies `test`.
template <class Test>
std::vector<glm::dvec3> interiorVertices(const std::vector<LoadedTile>& tiles, Test test) {
  std::vector<glm::dvec3> found;
  for (const LoadedTile& tile : tiles) {
    const uint32_t n = tile.block.verticesPerSide;
    for (uint32_t i = 1; i + 1 < n; ++i) {
      for (uint32_t j = 1; j + 1 < n; ++j) {
        bool all = true;
        for (uint32_t di = 0; di < 3 && all; ++di) {
          for (uint32_t dj = 0; dj < 3 && all; ++dj)
            all = test(tile.block.at(i + di - 1, j + dj - 1));
        }
        if (all) found.push_back(vertexPosition(tile, i, j));
      }
    }
  }
  return found;
}

bool isBlueish(const std::array<double, 3>& rgb) {
  return rgb[2] > rgb[0] + 30.0 && rgb[2] > rgb[1] + 15.0;
}

class TerrainScenes : public RenderTest {};

TEST_F(TerrainScenes, NoDataSeaIsBlueAndLandIsNot) {
  // Eastern England: the Humber mouth and the North Sea are no-data in the GTOPO30 crop.
  const auto tiles = loadTiles(11, -0.75, 53.55, 0.0, 54.0);
  ASSERT_GT(tiles.size(), 20u);
  upload(tiles);
  const LocalFrame frame = localFrame(-0.35, 53.8);
  const glm::dvec3 sun = glm::normalize(frame.up + 0.5 * frame.east - 0.5 * frame.north);
  const terrain::RenderView view = lookDownView(-0.35, 53.8, 45000.0, 40.0, kWidth, kHeight, sun);
  const Image image = drawAndRead(view, idsOf(tiles));
  savePng(image, "england_sea");

  const auto sea = interiorVertices(tiles, [](int16_t h) { return h == terrain::kNoDataHeight; });
  const auto land = interiorVertices(tiles, [](int16_t h) { return h >= 5; });
  // Projects each point and counts the pixels there (inside the image) and the blue-ish ones.
  auto classify = [&](const std::vector<glm::dvec3>& points, int& checked, int& blue) {
    for (const glm::dvec3& point : points) {
      const auto pixel = projectToPixel(view, point);
      if (!pixel || pixel->x < 1 || pixel->y < 1 || pixel->x >= kWidth - 1 ||
          pixel->y >= kHeight - 1) {
        continue;
      }
      ++checked;
      if (isBlueish(image.meanRgb(static_cast<int>(pixel->x), static_cast<int>(pixel->y), 0))) {
        ++blue;
      }
    }
  };
  int seaChecked = 0, seaBlue = 0, landChecked = 0, landBlue = 0;
  classify(sea, seaChecked, seaBlue);
  classify(land, landChecked, landBlue);
  ASSERT_GT(seaChecked, 30);
  ASSERT_GT(landChecked, 300);
  EXPECT_GE(seaBlue, seaChecked * 95 / 100) << seaBlue << " of " << seaChecked;
  EXPECT_EQ(landBlue, 0) << landBlue << " of " << landChecked;
}

struct FlankBrightness {
  double west = 0;
  double east = 0;
};

class MountFuji : public RenderTest {
 protected:
  void SetUp() override {
    RenderTest::SetUp();
    if (HasFatalFailure()) return;
    tiles_ = loadTiles(12, 138.45, 35.2, 139.0, 35.52);
    ASSERT_GT(tiles_.size(), 40u);
    upload(tiles_);
  }

  terrain::RenderView viewWithSun(double sunAzimuthDegrees) const {
    // Sun 30° above the horizon at the given azimuth (clockwise from north).
    const LocalFrame frame = localFrame(138.7274, 35.3606);
    const double azimuth = geo::degreesToRadians(sunAzimuthDegrees);
    const double elevation = geo::degreesToRadians(30.0);
    const glm::dvec3 sun =
        std::cos(elevation) * (std::sin(azimuth) * frame.east + std::cos(azimuth) * frame.north) +
        std::sin(elevation) * frame.up;
    return lookDownView(138.7274, 35.3606, 40000.0, 40.0, kWidth, kHeight, sun);
  }

  // Mean luminance around points ~4 km west and east of the summit, on the slopes.
  FlankBrightness flanks(const Image& image, const terrain::RenderView& view) const {
    FlankBrightness result;
    for (const auto& [longitude, target] :
         {std::pair{138.68, &result.west}, std::pair{138.775, &result.east}}) {
      const glm::dvec3 point =
          geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(longitude, 35.3606, 2000));
      const auto pixel = projectToPixel(view, point);
      EXPECT_TRUE(pixel.has_value());
      if (!pixel) continue;
      const auto rgb = image.meanRgb(static_cast<int>(pixel->x), static_cast<int>(pixel->y), 3);
      *target = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
    }
    return result;
  }

  static double luminanceStdDev(const Image& image) {
    double sum = 0, sumSquares = 0;
    int count = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        if (image.isBackground(x, y)) continue;
        const double l = image.luminance(x, y);
        sum += l;
        sumSquares += l * l;
        ++count;
      }
    }
    const double mean = sum / count;
    return std::sqrt(std::max(0.0, sumSquares / count - mean * mean));
  }

  std::vector<LoadedTile> tiles_;
};

TEST_F(MountFuji, FlanksFacingTheSunAreBrighter) {
  const terrain::RenderView fromWest = viewWithSun(270.0);
  const Image westLit = drawAndRead(fromWest, idsOf(tiles_));
  savePng(westLit, "fuji_sun_west");
  const terrain::RenderView fromEast = viewWithSun(90.0);
  const Image eastLit = drawAndRead(fromEast, idsOf(tiles_));
  savePng(eastLit, "fuji_sun_east");
  EXPECT_EQ(westLit.countNonBackground(), kWidth * kHeight);

  const FlankBrightness a = flanks(westLit, fromWest);
  const FlankBrightness b = flanks(eastLit, fromEast);
  // Same pixels, same colour ramp: only the lighting differs.
  EXPECT_GT(a.west, 1.25 * b.west) << a.west << " vs " << b.west;
  EXPECT_GT(b.east, 1.25 * a.east) << b.east << " vs " << a.east;
  EXPECT_GT(a.west, 1.25 * a.east);
  EXPECT_GT(b.east, 1.25 * b.west);
}

TEST_F(MountFuji, HillShadingAddsBrightnessVariation) {
  const terrain::RenderView view = viewWithSun(300.0);
  const Image shaded = drawAndRead(view, idsOf(tiles_));
  TerrainStyle flat = renderer_->style();
  flat.hillShading = false;
  renderer_->setStyle(flat);
  const Image unshaded = drawAndRead(view, idsOf(tiles_));
  savePng(shaded, "fuji_hillshaded");
  savePng(unshaded, "fuji_no_hillshading");
  const double shadedSpread = luminanceStdDev(shaded);
  const double flatSpread = luminanceStdDev(unshaded);
  EXPECT_GT(shadedSpread, 1.3 * flatSpread) << shadedSpread << " vs " << flatSpread;
}

class GroundLevel : public RenderTest {
 protected:
  void SetUp() override {
    RenderTest::SetUp();
    if (HasFatalFailure()) return;
    // Level-14 tiles (~1.2 km) around the lower south-western slope of Mount Fuji.
    tiles_ = loadTiles(14, 138.66, 35.27, 138.72, 35.33);
    ASSERT_GT(tiles_.size(), 20u);
    upload(tiles_);
    // The camera stands 1 m above a vertex in the middle of that area.
    const LoadedTile* centre = nullptr;
    for (const LoadedTile& tile : tiles_) {
      const geo::GlobeRectangle rect = geo::GeographicTilingScheme::tileRectangle(tile.id);
      if (rect.contains(geo::degreesToRadians(138.69), geo::degreesToRadians(35.30))) {
        centre = &tile;
      }
    }
    ASSERT_NE(centre, nullptr);
    const terrain::BlockGrid grid{centre->id, centre->block.verticesPerSide};
    longitudeDegrees_ = grid.longitudeDegrees(8);
    latitudeDegrees_ = grid.latitudeDegrees(8);
    groundHeightMeters_ = centre->block.surfaceHeightMetersAt(8, 8);
  }

  // 1 m above the ground, looking towards the summit (north-east), 8° below the horizon.
  terrain::RenderView view(double extraEastMeters = 0.0) const {
    const LocalFrame frame = localFrame(longitudeDegrees_, latitudeDegrees_);
    const glm::dvec3 eye = geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(
                                                               longitudeDegrees_, latitudeDegrees_,
                                                               groundHeightMeters_ + 1.0)) +
                           extraEastMeters * frame.east;
    const double pitch = geo::degreesToRadians(-8.0);
    const glm::dvec3 forward =
        std::cos(pitch) * glm::normalize(frame.north + frame.east) + std::sin(pitch) * frame.up;
    const glm::dvec3 sun = glm::normalize(frame.up + frame.north - frame.east);
    return terrain::makeLookAtView(eye, eye + forward, frame.up, geo::degreesToRadians(50.0),
                                   kWidth, kHeight, sun);
  }

  std::vector<LoadedTile> tiles_;
  double longitudeDegrees_ = 0, latitudeDegrees_ = 0, groundHeightMeters_ = 0;
};

TEST_F(GroundLevel, OneMetreAboveTheGroundSeesSolidTerrain) {
  const terrain::RenderView v = view();
  const Image image = drawAndRead(v, idsOf(tiles_));
  savePng(image, "fuji_1m_above_ground");
  // Rows are top-down: sky (background) along the top, ground everywhere in the lower half.
  int skyTop = 0;
  for (int x = 0; x < kWidth; ++x) skyTop += image.isBackground(x, 0) ? 1 : 0;
  EXPECT_GT(skyTop, kWidth * 9 / 10);
  int holes = 0;
  for (int y = kHeight / 2; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) holes += image.isBackground(x, y) ? 1 : 0;
  }
  EXPECT_EQ(holes, 0);
  EXPECT_GT(image.countNonBackground(), kWidth * kHeight / 2);
}

}  // namespace
}  // namespace globe::render::test
