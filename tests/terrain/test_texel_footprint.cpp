// The bound on base-level texels per pixel (terrain/texel_footprint.hpp) checked against rays:
// from many cameras, adjacent pixels' rays are intersected with the tangent planes of points on
// level ground in a tile, and the ground they span must never exceed the bound.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "geo/cartographic.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/texel_footprint.hpp"

namespace globe::terrain {
namespace {

const geo::Ellipsoid kEllipsoid = geo::Ellipsoid::wgs84();
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPixelAngle = 1e-3;

// The most ground (metres along the point's tangent plane) one pixel's angle spans next to the
// ray from the camera to the point, over sixteen directions; infinity where a ray misses.
double groundPerPixelMeters(const glm::dvec3& camera, const glm::dvec3& point,
                            const glm::dvec3& normal) {
  const glm::dvec3 ray = glm::normalize(point - camera);
  const glm::dvec3 side = glm::normalize(
      glm::cross(ray, std::abs(ray.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0)));
  const glm::dvec3 other = glm::cross(ray, side);
  double most = 0.0;
  for (int k = 0; k < 16; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / 16.0;
    const glm::dvec3 step = std::cos(phi) * side + std::sin(phi) * other;
    const glm::dvec3 next = glm::normalize(ray + std::tan(kPixelAngle) * step);
    const double along = glm::dot(next, normal);
    if (!(along < 0.0)) return kInfinity;
    const double t = glm::dot(point - camera, normal) / along;
    most = std::max(most, glm::distance(camera + t * next, point));
  }
  return most;
}

struct Ground {
  std::vector<glm::dvec3> points, normals;
  TileBounds bounds;
};

// Level ground between two heights over a square of `sizeDegrees` at (lon, lat) and its sphere.
Ground levelGround(double lonDegrees, double latDegrees, double sizeDegrees, double lowMeters,
                   double highMeters) {
  Ground ground;
  for (int i = 0; i <= 8; ++i) {
    for (int j = 0; j <= 8; ++j) {
      for (double height : {lowMeters, highMeters}) {
        const auto where = geo::Cartographic::fromDegrees(lonDegrees + sizeDegrees * i / 8,
                                                          latDegrees + sizeDegrees * j / 8, height);
        ground.points.push_back(geo::cartographicToEcef(kEllipsoid, where));
        ground.normals.push_back(geo::geodeticSurfaceNormal(kEllipsoid, where));
        ground.bounds.centerEcefMeters += ground.points.back();
      }
    }
  }
  TileBounds& b = ground.bounds;
  b.centerEcefMeters /= static_cast<double>(ground.points.size());
  b.upEcef = glm::normalize(b.centerEcefMeters);  // geocentric, as the renderer's
  b.topMeters = -kInfinity;
  for (const glm::dvec3& p : ground.points) {
    b.radiusMeters = std::max(b.radiusMeters, glm::distance(p, b.centerEcefMeters));
    b.topMeters = std::max(b.topMeters, glm::dot(p - b.centerEcefMeters, b.upEcef));
  }
  return ground;
}

TEST(TexelFootprint, NoPixelOnLevelGroundSpansMoreTexelsThanTheBound) {
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int bounded = 0, tight = 0;
  for (int tile = 0; tile < 60; ++tile) {
    const double size = std::pow(10.0, -3.0 + 3.0 * unit(random));  // 0.001 to 1 degree
    const double lat = -80.0 + 160.0 * unit(random);
    const Ground ground = levelGround(-180.0 + 350.0 * unit(random), lat, size,
                                      -500.0 + 3000.0 * unit(random), 3000.0 + 2000 * unit(random));
    const TileBounds& b = ground.bounds;
    const double texelMeters = 0.5 + 50.0 * unit(random);
    for (int c = 0; c < 60; ++c) {
      // Above the tile's top by 0.001 to 30 tile radii, up to 50 radii to the side: straight
      // down to grazing.
      const double height = b.radiusMeters * std::pow(10.0, -3.0 + 4.5 * unit(random));
      const double side = b.radiusMeters * std::pow(10.0, -1.0 + 2.7 * unit(random));
      const double heading = 2.0 * std::numbers::pi * unit(random);
      const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), b.upEcef));
      const glm::dvec3 north = glm::cross(b.upEcef, east);
      const glm::dvec3 camera = b.centerEcefMeters + b.upEcef * (b.topMeters + height) +
                                side * (std::cos(heading) * east + std::sin(heading) * north);
      const double bound = maxTexelsPerPixel(camera, b, texelMeters, kPixelAngle, kEllipsoid);
      if (!std::isfinite(bound)) continue;
      ++bounded;
      double most = 0.0;
      for (size_t p = 0; p < ground.points.size(); ++p) {
        most = std::max(
            most, groundPerPixelMeters(camera, ground.points[p], ground.normals[p]) / texelMeters);
      }
      ASSERT_LE(most, bound) << "tile " << tile << " camera " << c << " size " << size;
      if (bound < 3.0 * most) ++tight;
    }
  }
  // Most cameras get a bound, and most bounds are within 3x of what the rays show.
  EXPECT_GT(bounded, 1800);
  EXPECT_GT(tight, bounded / 2);
}

TEST(TexelFootprint, SeenFromStraightAboveTheBoundIsNearTheTruth) {
  const Ground ground = levelGround(-113.0, 37.2, 0.01, 1500.0, 1500.0);  // ~1 km, flat
  const TileBounds& b = ground.bounds;
  const glm::dvec3 camera = b.centerEcefMeters + b.upEcef * 7000.0;
  const double texelMeters = 30.0;
  const double bound = maxTexelsPerPixel(camera, b, texelMeters, kPixelAngle, kEllipsoid);
  double most = 0.0;
  for (size_t p = 0; p < ground.points.size(); ++p) {
    most = std::max(most, groundPerPixelMeters(camera, ground.points[p], ground.normals[p]));
  }
  // 7 m per pixel at 7 km: a 30 m texel covers ~4 pixels, magnified.
  EXPECT_NEAR(most, 7.0, 0.2);
  EXPECT_GE(bound, most / texelMeters);
  EXPECT_LT(bound, 1.5 * most / texelMeters);
  EXPECT_LT(bound, 0.5);
}

TEST(TexelFootprint, UnboundedWhenTheCameraIsNotAboveOrAnInputIsBad) {
  const glm::dvec3 up(0, 0, 1), center(0, 0, 6.4e6);
  auto rho = [&](glm::dvec3 camera, double texel = 10.0, double pixel = kPixelAngle,
                 double radius = 1000.0, double top = 100.0,
                 glm::dvec3 tileUp = glm::dvec3(0, 0, 1)) {
    return maxTexelsPerPixel(camera, {center, radius, tileUp, top}, texel, pixel, kEllipsoid);
  };
  EXPECT_TRUE(std::isfinite(rho(center + up * 5000.0)));
  EXPECT_TRUE(std::isfinite(rho(center + up * 150.0)));        // just over the top
  EXPECT_EQ(rho(center + up * 90.0), kInfinity);               // below the top
  EXPECT_EQ(rho(center + glm::dvec3(1e5, 0, 50)), kInfinity);  // beside it, below its top
  EXPECT_EQ(rho(center - up * 5000.0), kInfinity);             // underneath
  EXPECT_EQ(rho(glm::dvec3(std::nan(""), 0, 0)), kInfinity);
  EXPECT_EQ(rho(center + up * 5000.0, 0.0), kInfinity);
  EXPECT_EQ(rho(center + up * 5000.0, std::nan("")), kInfinity);
  EXPECT_EQ(rho(center + up * 5000.0, 10.0, std::nan("")), kInfinity);
  EXPECT_EQ(rho(center + up * 5000.0, 10.0, kPixelAngle, std::nan("")), kInfinity);
  EXPECT_EQ(rho(center + up * 5000.0, 10.0, kPixelAngle, kInfinity), kInfinity);
  EXPECT_EQ(rho(center + up * 5000.0, 10.0, kPixelAngle, 1000.0, -kInfinity),
            kInfinity);  // no vertex
  EXPECT_EQ(rho(center + up * 5000.0, 10.0, kPixelAngle, 1000.0, 100.0, glm::dvec3(0)), kInfinity);
  EXPECT_EQ(rho(center + up * 5000.0, 10.0, kPixelAngle, 1000.0, 100.0, up * 2.0), kInfinity);
  EXPECT_EQ(rho(center + up * kInfinity), kInfinity);
  // Farther is more texels per pixel; a coarser texel fewer.
  EXPECT_LT(rho(center + up * 5000.0), rho(center + up * 50000.0));
  EXPECT_GT(rho(center + up * 5000.0), rho(center + up * 5000.0, 20.0));
}

TEST(TexelFootprint, ShortestTexelSide) {
  const double a = kEllipsoid.semiMajorAxisMeters, b = kEllipsoid.semiMinorAxisMeters;
  // Level 10 at the equator (row 511 reaches 0 deg from the north): north-south is shorter.
  const geo::TileId equator{10, 100, 511};
  const double side = std::numbers::pi / 1024.0;
  EXPECT_NEAR(shortestTexelMeters(equator, 256, 256, kEllipsoid), b * b / a * side / 256, 1e-9);
  // At 60 deg north the parallel is half the equator: east-west is shorter.
  const auto north =
      geo::GeographicTilingScheme::positionToTile(0.1, 60.5 * std::numbers::pi / 180, 10);
  ASSERT_TRUE(north.has_value());
  const geo::GlobeRectangle rect = geo::GeographicTilingScheme::tileRectangle(*north);
  EXPECT_NEAR(shortestTexelMeters(*north, 256, 128, kEllipsoid),
              a * std::cos(rect.northRadians) * side / 256, 1e-9);
  // A tile touching a pole has no shortest side; bad sizes and tiles give 0.
  EXPECT_EQ(shortestTexelMeters({0, 0, 0}, 256, 256, kEllipsoid), 0.0);
  EXPECT_EQ(shortestTexelMeters(equator, 0, 256, kEllipsoid), 0.0);
  EXPECT_EQ(shortestTexelMeters({3, 99, 0}, 256, 256, kEllipsoid), 0.0);
}

TEST(TexelFootprint, PixelAngleFromTheProjection) {
  RenderView view;
  view.widthPixels = 1280;
  view.heightPixels = 720;
  view.projection = makePerspective(std::numbers::pi / 3, 1280.0 / 720.0, 1.0, 1e7);
  EXPECT_NEAR(pixelAngleRadians(view), 2 * std::atan(std::tan(std::numbers::pi / 6) / 720), 1e-12);
  view.heightPixels = 0;
  EXPECT_TRUE(std::isnan(pixelAngleRadians(view)));
}

}  // namespace
}  // namespace globe::terrain
