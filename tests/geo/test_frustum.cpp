// Tests for geo/frustum.hpp: plane extraction and conservative frustum culling of regions.
#include "geo/frustum.hpp"

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "region_sampling.hpp"

namespace globe::geo {
namespace {

bool insideFrustum(const Frustum& frustum, const glm::dvec3& p) {
  for (const Plane& plane : frustum.planes) {
    if (glm::dot(plane.normal, p) + plane.distance < 0.0) return false;
  }
  return true;
}

glm::dmat4 viewProjection(const glm::dvec3& eye, const glm::dvec3& target, double fovyRadians,
                          double aspect, double nearMeters, double farMeters) {
  const glm::dvec3 forward = glm::normalize(target - eye);
  const glm::dvec3 up = std::abs(forward.z) < 0.9 ? glm::dvec3{0, 0, 1} : glm::dvec3{1, 0, 0};
  return glm::perspective(fovyRadians, aspect, nearMeters, farMeters) *
         glm::lookAt(eye, target, up);
}

TEST(Frustum, IdentityGivesTheClipCube) {
  const Frustum f = Frustum::fromViewProjection(glm::dmat4{1.0});
  const glm::dvec3 normals[] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(f.planes[i].normal, normals[i]) << i;
    EXPECT_EQ(f.planes[i].distance, 1.0) << i;
  }
}

TEST(Frustum, PlanesMatchClipSpace) {
  std::mt19937_64 rng(51);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const glm::dvec3 eye{7e6, 1e6, -2e6};
  const glm::dmat4 vp = viewProjection(eye, {0, 0, 0}, 0.8, 1.5, 10.0, 1e7);
  const Frustum f = Frustum::fromViewProjection(vp);
  for (const Plane& plane : f.planes) EXPECT_NEAR(glm::length(plane.normal), 1.0, 1e-12);
  int inside = 0;
  for (int i = 0; i < 100000; ++i) {
    const glm::dvec3 p = eye + 1e7 * glm::dvec3{unit(rng), unit(rng), unit(rng)};
    const glm::dvec4 clip = vp * glm::dvec4{p, 1.0};
    const double slack =
        std::min({clip.w - std::abs(clip.x), clip.w - std::abs(clip.y), clip.w - std::abs(clip.z)});
    if (std::abs(slack) < 1e-6 * std::abs(clip.w)) continue;  // too close to call
    ASSERT_EQ(insideFrustum(f, p), slack > 0.0);
    inside += slack > 0.0;
  }
  EXPECT_GT(inside, 1000);
}

TEST(Frustum, InfiniteFarPlaneIsAllInside) {
  const glm::dmat4 vp = glm::infinitePerspective(1.0, 1.0, 1.0) *
                        glm::lookAt(glm::dvec3{0, 0, 10}, glm::dvec3{0.0}, glm::dvec3{0, 1, 0});
  const Frustum f = Frustum::fromViewProjection(vp);
  EXPECT_EQ(f.planes[5].normal, glm::dvec3{0.0});
  EXPECT_EQ(f.planes[5].distance, 0.0);
  EXPECT_TRUE(insideFrustum(f, {0, 0, -1e12}));
  EXPECT_FALSE(insideFrustum(f, {0, 0, 20}));
}

TEST(Frustum, ObviousCases) {
  const Ellipsoid e = Ellipsoid::wgs84();
  const glm::dvec3 eye = cartographicToEcef(e, Cartographic::fromDegrees(0, 0, 1e6));
  const BoundingRegion below{GlobeRectangle::fromDegrees(-1, -1, 1, 1), -100, 5000};
  // Looking straight up, away from the earth: the region below is behind the camera.
  const Frustum up =
      Frustum::fromViewProjection(viewProjection(eye, eye * 2.0, 1.0, 1.0, 1.0, 1e8));
  EXPECT_EQ(cullRegion(up, below, e), CullResult::Outside);
  // Looking down at it with a wide field of view: fully inside.
  const Frustum down =
      Frustum::fromViewProjection(viewProjection(eye, glm::dvec3{0.0}, 1.5, 1.0, 1.0, 1e8));
  EXPECT_EQ(cullRegion(down, below, e), CullResult::Inside);
  // A level-0 tile straddles the view.
  EXPECT_EQ(cullRegion(down, {GeographicTilingScheme::tileRectangle({0, 1, 0}), 0, 0}, e),
            CullResult::Intersecting);
  // Beyond the far plane.
  const Frustum shortSight =
      Frustum::fromViewProjection(viewProjection(eye, glm::dvec3{0.0}, 1.5, 1.0, 1.0, 5e5));
  EXPECT_EQ(cullRegion(shortSight, below, e), CullResult::Outside);
  // Invalid regions are never culled.
  EXPECT_EQ(cullRegion(up, {below.rectangle, 10, 0}, e), CullResult::Intersecting);
}

// Conservativeness: Outside only if no sampled point is inside the frustum; Inside only if all
// are. Cameras look at the globe near the region so that all three outcomes happen often.
TEST(Frustum, ConservativeForRandomFrustumsAndRegions) {
  std::mt19937_64 rng(52);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int counts[3] = {0, 0, 0};
  for (int trial = 0; trial < 20000; ++trial) {
    const Ellipsoid e = trial % 2 == 0 ? Ellipsoid::wgs84() : Ellipsoid::sphere();
    const Cartographic cameraCarto{(2.0 * unit(rng) - 1.0) * std::numbers::pi,
                                   std::asin(2.0 * unit(rng) - 1.0),
                                   std::pow(10.0, 2.0 + 5.5 * unit(rng))};
    const glm::dvec3 eye = cartographicToEcef(e, cameraCarto);
    // Look at a ground point up to a few camera heights away, or anywhere half the time.
    const double spread = std::min(1.0, 3.0 * cameraCarto.heightMeters / 6.4e6);
    const Cartographic targetCarto =
        unit(rng) < 0.5
            ? Cartographic{wrapLongitudeRadians(cameraCarto.longitudeRadians +
                                                (unit(rng) - 0.5) * spread),
                           std::clamp(cameraCarto.latitudeRadians + (unit(rng) - 0.5) * spread,
                                      -std::numbers::pi / 2.0, std::numbers::pi / 2.0),
                           0.0}
            : Cartographic{(2.0 * unit(rng) - 1.0) * std::numbers::pi,
                           (unit(rng) - 0.5) * std::numbers::pi, 0.0};
    const glm::dvec3 target = cartographicToEcef(e, targetCarto);
    if (glm::length(target - eye) < 1.0) continue;
    // Drawn one per statement: the evaluation order of function arguments is unspecified.
    const double fovy = 0.2 + 1.5 * unit(rng);
    const double aspect = 0.5 + 1.5 * unit(rng);
    const double nearMeters = std::pow(10.0, 4.0 * unit(rng));
    const double farMeters = std::pow(10.0, 5.0 + 3.0 * unit(rng));
    const Frustum frustum = Frustum::fromViewProjection(
        viewProjection(eye, target, fovy, aspect, nearMeters, farMeters));
    // The region: a tile of random level near the target (or the camera's nadir).
    const uint32_t level = static_cast<uint32_t>(unit(rng) * 18.0);
    const Cartographic& anchor = unit(rng) < 0.8 ? targetCarto : cameraCarto;
    const TileId tile = *GeographicTilingScheme::positionToTile(anchor.longitudeRadians,
                                                                anchor.latitudeRadians, level);
    double minimum = 0.0;
    double maximum = 0.0;
    testing::randomHeights(rng, minimum, maximum);
    const BoundingRegion region{GeographicTilingScheme::tileRectangle(tile), minimum, maximum};
    const CullResult result = cullRegion(frustum, RegionVolume::fromRegion(region, e));
    ++counts[static_cast<int>(result)];
    if (result == CullResult::Intersecting) continue;
    for (int s = 0; s < 200; ++s) {
      const glm::dvec3 q = testing::sampleRegionPoint(rng, region, e);
      ASSERT_EQ(insideFrustum(frustum, q), result == CullResult::Inside)
          << "trial " << trial << " level " << level;
    }
  }
  std::cout << "[ frustum ] outside " << counts[0] << ", intersecting " << counts[1] << ", inside "
            << counts[2] << "\n";
  EXPECT_GT(counts[0], 1000);
  EXPECT_GT(counts[1], 1000);
  EXPECT_GT(counts[2], 500);
}

}  // namespace
}  // namespace globe::geo
