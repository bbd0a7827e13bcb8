// Tests for geo/ellipsoid.hpp: WGS84 constants, the sphere and globe model names.
#include "geo/ellipsoid.hpp"

#include <gtest/gtest.h>

namespace globe::geo {
namespace {

TEST(Ellipsoid, Wgs84Constants) {
  constexpr Ellipsoid wgs84 = Ellipsoid::wgs84();
  static_assert(!wgs84.isSphere());
  EXPECT_EQ(wgs84.semiMajorAxisMeters, 6378137.0);
  EXPECT_NEAR(wgs84.semiMinorAxisMeters, 6356752.314245179, 1e-8);
  EXPECT_NEAR(wgs84.eccentricitySquared(), 6.69437999014e-3, 1e-14);
}

TEST(Ellipsoid, Sphere) {
  constexpr Ellipsoid sphere = Ellipsoid::sphere();
  static_assert(sphere.isSphere());
  static_assert(sphere.eccentricitySquared() == 0.0);
  EXPECT_EQ(sphere.semiMajorAxisMeters, 6371000.0);
  EXPECT_EQ(Ellipsoid::sphere(1000.0).semiMinorAxisMeters, 1000.0);
}

TEST(Ellipsoid, ModelSelection) {
  EXPECT_EQ(ellipsoidFor(GlobeModel::Wgs84).semiMajorAxisMeters, 6378137.0);
  EXPECT_TRUE(ellipsoidFor(GlobeModel::Sphere).isSphere());
}

TEST(Ellipsoid, ParseAndPrintModelNames) {
  EXPECT_EQ(parseGlobeModel("wgs84"), GlobeModel::Wgs84);
  EXPECT_EQ(parseGlobeModel("sphere"), GlobeModel::Sphere);
  EXPECT_EQ(parseGlobeModel("WGS84"), GlobeModel::Wgs84);
  EXPECT_EQ(parseGlobeModel(""), std::nullopt);
  EXPECT_EQ(parseGlobeModel("wgs8"), std::nullopt);
  EXPECT_EQ(parseGlobeModel("wgs84 "), std::nullopt);
  EXPECT_EQ(parseGlobeModel("spheres"), std::nullopt);
  for (const GlobeModel model : {GlobeModel::Wgs84, GlobeModel::Sphere}) {
    EXPECT_EQ(parseGlobeModel(toString(model)), model);
  }
  EXPECT_EQ(toString(GlobeModel::Wgs84), "wgs84");
  EXPECT_EQ(toString(GlobeModel::Sphere), "sphere");
}

}  // namespace
}  // namespace globe::geo
