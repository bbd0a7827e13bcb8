// Tests for geo/globe_rectangle.hpp.
#include "geo/globe_rectangle.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace globe::geo {
namespace {

TEST(GlobeRectangle, SizesAndCenter) {
  const GlobeRectangle r = GlobeRectangle::fromDegrees(-180.0, -90.0, 0.0, 90.0);
  EXPECT_EQ(r.westRadians, -std::numbers::pi);
  EXPECT_EQ(r.southRadians, -std::numbers::pi / 2.0);
  EXPECT_EQ(r.eastRadians, 0.0);
  EXPECT_EQ(r.northRadians, std::numbers::pi / 2.0);
  EXPECT_EQ(r.widthRadians(), std::numbers::pi);
  EXPECT_EQ(r.heightRadians(), std::numbers::pi);
  const Cartographic c = r.center();
  EXPECT_EQ(c.longitudeRadians, -std::numbers::pi / 2.0);
  EXPECT_EQ(c.latitudeRadians, 0.0);
  EXPECT_EQ(c.heightMeters, 0.0);
}

TEST(GlobeRectangle, ContainsIsClosed) {
  const GlobeRectangle r = GlobeRectangle::fromDegrees(10.0, 20.0, 30.0, 40.0);
  EXPECT_TRUE(r.contains(r.westRadians, r.southRadians));
  EXPECT_TRUE(r.contains(r.eastRadians, r.northRadians));
  EXPECT_TRUE(r.contains(r.center().longitudeRadians, r.center().latitudeRadians));
  EXPECT_FALSE(r.contains(std::nextafter(r.westRadians, -1.0), r.southRadians));
  EXPECT_FALSE(r.contains(r.eastRadians, std::nextafter(r.northRadians, 2.0)));
  EXPECT_FALSE(r.contains(std::nan(""), r.southRadians));
}

TEST(GlobeRectangle, Intersects) {
  const GlobeRectangle r = GlobeRectangle::fromDegrees(10.0, 20.0, 30.0, 40.0);
  EXPECT_TRUE(r.intersects(r));
  EXPECT_TRUE(r.intersects(GlobeRectangle::fromDegrees(25.0, 35.0, 50.0, 60.0)));
  EXPECT_TRUE(r.intersects(GlobeRectangle::fromDegrees(15.0, 25.0, 20.0, 30.0)));  // inside
  EXPECT_TRUE(GlobeRectangle::fromDegrees(15.0, 25.0, 20.0, 30.0).intersects(r));
  EXPECT_TRUE(r.intersects(GlobeRectangle::fromDegrees(30.0, 40.0, 50.0, 60.0)));  // corner
  EXPECT_TRUE(r.intersects(GlobeRectangle::fromDegrees(0.0, 0.0, 10.0, 20.0)));
  EXPECT_FALSE(r.intersects(GlobeRectangle::fromDegrees(31.0, 20.0, 50.0, 40.0)));
  EXPECT_FALSE(r.intersects(GlobeRectangle::fromDegrees(10.0, -40.0, 30.0, 19.0)));
  EXPECT_FALSE(r.intersects(GlobeRectangle::fromDegrees(-30.0, 20.0, 9.0, 40.0)));
}

}  // namespace
}  // namespace globe::geo
