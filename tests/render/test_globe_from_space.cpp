// The whole globe from space, rendered from real level-3 tiles: the lit disc matches a ray-cast
// ellipsoid, nothing inside it is left black, oceans are blue and deserts are not.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geo/ecef.hpp"
#include "tests/render/render_test_support.hpp"

namespace globe::render::test {
namespace {

struct DiscComparison {
  int expected = 0;       // pixels whose centre ray hits the ellipsoid
  int drawn = 0;          // non-background pixels
  int missingInside = 0;  // background pixels well inside the disc
  int strayOutside = 0;   // drawn pixels well outside the disc
};

// Compares the image with the ray-cast ellipsoid; "well" inside/outside: all four pixel corners
// (±1.5 px) agree, with the ellipsoid grown/shrunk by 10 km for the terrain's relief.
DiscComparison compareWithDisc(const Image& image, const terrain::RenderView& view) {
  DiscComparison result;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const double cx = x + 0.5, cy = y + 0.5;
      if (rayHitsEllipsoid(view, cx, cy, 0.0)) ++result.expected;
      const bool background = image.isBackground(x, y);
      if (!background) ++result.drawn;
      bool allInside = true, allOutside = true;
      for (const double dx : {-1.5, 1.5}) {
        for (const double dy : {-1.5, 1.5}) {
          allInside = allInside && rayHitsEllipsoid(view, cx + dx, cy + dy, -10000.0);
          allOutside = allOutside && !rayHitsEllipsoid(view, cx + dx, cy + dy, 10000.0);
        }
      }
      if (allInside && background) ++result.missingInside;
      if (allOutside && !background) ++result.strayOutside;
    }
  }
  return result;
}

class GlobeFromSpace : public RenderTest {};

TEST_F(GlobeFromSpace, DiscMatchesTheEllipsoidAndIsFullyLit) {
  const auto tiles = loadTiles(3, -180, -90, 180, 90);
  ASSERT_EQ(tiles.size(), 128u);
  upload(tiles);
  // Four earth radii from the centre, above (20°E, 10°N); the sun behind the camera.
  const glm::dvec3 direction =
      geo::geodeticSurfaceNormal(kWgs84, geo::Cartographic::fromDegrees(20.0, 10.0, 0.0));
  const glm::dvec3 eye = 4.0 * kWgs84.semiMajorAxisMeters * direction;
  const terrain::RenderView view =
      terrain::makeLookAtView(eye, glm::dvec3(0.0), glm::dvec3(0, 0, 1),
                              geo::degreesToRadians(40.0), kWidth, kHeight, direction);
  FrameStats stats;
  const Image image = drawAndRead(view, idsOf(tiles), &stats);
  savePng(image, "globe_from_space");
  EXPECT_EQ(stats.tilesDrawn, 128u);
  EXPECT_EQ(stats.drawCalls, 128u);

  const DiscComparison disc = compareWithDisc(image, view);
  // Analytic: angular radius asin(1/4), 40° field of view over 240 rows: r ≈ 85 px.
  const double radius = std::tan(std::asin(0.25)) / std::tan(geo::degreesToRadians(20.0)) * 120.0;
  EXPECT_NEAR(disc.expected, std::numbers::pi * radius * radius, 0.02 * disc.expected);
  EXPECT_NEAR(disc.drawn, disc.expected, 0.01 * disc.expected);
  EXPECT_EQ(disc.missingInside, 0);  // no black (NaN or unlit) pixel inside the disc
  EXPECT_EQ(disc.strayOutside, 0);

  // Ocean (mid-Atlantic, ETOPO20 sea floor below 0 m) is blue; the Sahara is not.
  const auto atlantic = projectToPixel(
      view, geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(-5.0, -5.0, 0.0)));
  const auto sahara = projectToPixel(
      view, geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(15.0, 23.0, 0.0)));
  ASSERT_TRUE(atlantic && sahara);
  const auto sea = image.meanRgb(static_cast<int>(atlantic->x), static_cast<int>(atlantic->y), 2);
  const auto land = image.meanRgb(static_cast<int>(sahara->x), static_cast<int>(sahara->y), 2);
  EXPECT_GT(sea[2], sea[0] + 40) << sea[0] << " " << sea[1] << " " << sea[2];
  EXPECT_GT(sea[2], sea[1] + 20);
  EXPECT_GT(land[0], land[2] + 20) << land[0] << " " << land[1] << " " << land[2];
}

TEST_F(GlobeFromSpace, NightSideIsDarkButNotBlack) {
  const auto tiles = loadTiles(3, -180, -90, 180, 90);
  upload(tiles);
  const glm::dvec3 direction =
      geo::geodeticSurfaceNormal(kWgs84, geo::Cartographic::fromDegrees(-60.0, 20.0, 0.0));
  const glm::dvec3 eye = 4.0 * kWgs84.semiMajorAxisMeters * direction;
  // The sun 90° east, then 90° west of the view: the other half of the disc is in the night.
  auto render = [&](double sunLongitudeDegrees) {
    const glm::dvec3 sun = geo::geodeticSurfaceNormal(
        kWgs84, geo::Cartographic::fromDegrees(sunLongitudeDegrees, 0.0, 0.0));
    const terrain::RenderView view =
        terrain::makeLookAtView(eye, glm::dvec3(0.0), glm::dvec3(0, 0, 1),
                                geo::degreesToRadians(40.0), kWidth, kHeight, sun);
    const Image image = drawAndRead(view, idsOf(tiles));
    EXPECT_EQ(compareWithDisc(image, view).missingInside, 0);  // dark, never black
    return image;
  };
  const Image eastLit = render(30.0);
  const Image westLit = render(-150.0);
  savePng(eastLit, "globe_terminator");
  // Same pixels, same colours: a quarter of the disc on each side, lit and then in the night.
  auto sum = [](const Image& image, int x0) {
    double total = 0;
    for (int y = 100; y < 140; ++y) {
      for (int x = x0; x < x0 + 20; ++x) total += image.luminance(x, y);
    }
    return total;
  };
  const int left = kWidth / 2 - 70, right = kWidth / 2 + 50;
  EXPECT_GT(sum(eastLit, right), 1.8 * sum(westLit, right));
  EXPECT_GT(sum(westLit, left), 1.8 * sum(eastLit, left));
}

TEST_F(GlobeFromSpace, From40000KilometresTheGlobeIsASmallDisc) {
  const auto tiles = loadTiles(2, -180, -90, 180, 90);
  ASSERT_EQ(tiles.size(), 32u);
  upload(tiles);
  const glm::dvec3 direction =
      geo::geodeticSurfaceNormal(kWgs84, geo::Cartographic::fromDegrees(140.0, 30.0, 0.0));
  const glm::dvec3 eye =
      geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(140.0, 30.0, 4.0e7));
  const terrain::RenderView view =
      terrain::makeLookAtView(eye, glm::dvec3(0.0), glm::dvec3(0, 0, 1),
                              geo::degreesToRadians(30.0), kWidth, kHeight, direction);
  const Image image = drawAndRead(view, idsOf(tiles));
  savePng(image, "globe_from_40000km");
  const DiscComparison disc = compareWithDisc(image, view);
  EXPECT_GT(disc.expected, 10000);
  EXPECT_NEAR(disc.drawn, disc.expected, 0.015 * disc.expected);
  EXPECT_EQ(disc.missingInside, 0);
  EXPECT_EQ(disc.strayOutside, 0);
}

}  // namespace
}  // namespace globe::render::test
