// The bound on base-level texels per pixel (terrain/texel_footprint.hpp) checked against rays:
// from many cameras, adjacent pixels' rays are intersected with the tangent planes of points on
// level ground in a tile, and the ground they span must never exceed the bound.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <span>
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
  TileBox box;
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
      }
    }
  }
  glm::dvec3 center(0.0);
  for (const glm::dvec3& p : ground.points) center += p;
  center /= static_cast<double>(ground.points.size());
  std::vector<glm::dvec3> offsets;
  for (const glm::dvec3& p : ground.points) offsets.push_back(p - center);
  ground.box = makeTileBox(center, offsets);
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
    const TileBox& b = ground.box;
    const double radius = glm::length(glm::max(-b.minMeters, b.maxMeters));
    const glm::dvec3 up = b.axes[2];
    const double texelMeters = 0.5 + 50.0 * unit(random);
    for (int c = 0; c < 60; ++c) {
      // Above the tile's top by 0.001 to 30 tile radii, up to 50 radii to the side: straight
      // down to grazing.
      const double height = radius * std::pow(10.0, -3.0 + 4.5 * unit(random));
      const double side = radius * std::pow(10.0, -1.0 + 2.7 * unit(random));
      const double heading = 2.0 * std::numbers::pi * unit(random);
      const glm::dvec3 camera =
          b.centerEcefMeters + up * (b.maxMeters.z + height) +
          side * (std::cos(heading) * b.axes[0] + std::sin(heading) * b.axes[1]);
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
  const TileBox& b = ground.box;
  const glm::dvec3 camera = b.centerEcefMeters + b.axes[2] * 7000.0;
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
  // A 2 km square 200 m thick (its top 100 m above the centre) at the north pole's latitude 60.
  const glm::dvec3 center =
      geo::cartographicToEcef(kEllipsoid, geo::Cartographic::fromDegrees(10.0, 60.0, 0.0));
  const std::vector<glm::dvec3> corners = [&] {
    const TileBox frame = makeTileBox(center, {});
    std::vector<glm::dvec3> points;
    for (double x : {-1000.0, 1000.0})
      for (double y : {-1000.0, 1000.0})
        for (double z : {-100.0, 100.0})
          points.push_back(x * frame.axes[0] + y * frame.axes[1] + z * frame.axes[2]);
    return points;
  }();
  const TileBox box = makeTileBox(center, corners);
  const glm::dvec3 up = box.axes[2];
  EXPECT_NEAR(box.maxMeters.z, 100.0, 1e-9);
  EXPECT_NEAR(box.minMeters.x, -1000.0, 1e-9);
  auto rho = [&](glm::dvec3 camera, double texel = 10.0, double pixel = kPixelAngle) {
    return maxTexelsPerPixel(camera, box, texel, pixel, kEllipsoid);
  };
  EXPECT_TRUE(std::isfinite(rho(center + up * 5000.0)));
  EXPECT_TRUE(std::isfinite(rho(center + up * 150.0)));               // just over the top
  EXPECT_EQ(rho(center + up * 90.0), kInfinity);                      // below the top
  EXPECT_EQ(rho(center + box.axes[0] * 1e5 + up * 50.0), kInfinity);  // beside it, below its top
  EXPECT_EQ(rho(center - up * 5000.0), kInfinity);                    // underneath
  EXPECT_EQ(rho(glm::dvec3(std::nan(""), 0, 0)), kInfinity);
  EXPECT_EQ(rho(center + up * 5000.0, 0.0), kInfinity);
  EXPECT_EQ(rho(center + up * 5000.0, std::nan("")), kInfinity);
  EXPECT_EQ(rho(center + up * 5000.0, 10.0, std::nan("")), kInfinity);
  EXPECT_EQ(rho(center + up * kInfinity), kInfinity);
  EXPECT_EQ(maxTexelsPerPixel(center + up * 5000.0, makeTileBox(center, {}), 10.0, kPixelAngle,
                              kEllipsoid),
            kInfinity);  // no vertex
  EXPECT_EQ(maxTexelsPerPixel(center, makeTileBox(glm::dvec3(0.0), corners), 10.0, kPixelAngle,
                              kEllipsoid),
            kInfinity);  // no up at the Earth's centre
  // Farther is more texels per pixel; a coarser texel fewer.
  EXPECT_LT(rho(center + up * 5000.0), rho(center + up * 50000.0));
  EXPECT_GT(rho(center + up * 5000.0), rho(center + up * 5000.0, 20.0));
  // 5 km over the top, the farthest corner is sqrt(5200² + 2·1000²) away: the bound is that
  // squared · α / (5000 · texel), the tilt adding under 1 % (the sphere around the box would
  // give 1.46x that).
  const double cornerSquared = 5200.0 * 5200.0 + 2e6;
  const double expected = cornerSquared * kPixelAngle / (5000.0 * 10.0);
  EXPECT_GE(rho(center + up * 5100.0), expected);
  EXPECT_LT(rho(center + up * 5100.0), 1.01 * expected);
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
