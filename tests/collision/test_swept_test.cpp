// Swept tests through Mount Fuji: a fast level move across it tunnels with the paper's end-point
// test and stops at the first contact with the sweep, at any speed; an orbit is lifted over it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include <glm/geometric.hpp>

#include "collision/collision_response.hpp"
#include "collision/swept_test.hpp"
#include "geo/ecef.hpp"
#include "tests/camera/controller_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::collision {
namespace {

using camera::testing::drawnHeight;
using camera::testing::fujiArray;
using camera::testing::fujiSummit;
using camera::testing::offsetPosition;
using globe::test::kClearance;
constexpr double kHeight = 3400.0;  // below the summit (~3731 m drawn), above both flanks
using globe::test::kWgs84;

using camera::testing::drawn;
using camera::testing::fuji;

struct Crossing {
  geo::Cartographic west, east;
};
Crossing crossing(double lengthMeters) {
  return {offsetPosition(fujiSummit(), 1.5 * std::numbers::pi, lengthMeters / 2, kHeight),
          offsetPosition(fujiSummit(), 0.5 * std::numbers::pi, lengthMeters / 2, kHeight)};
}

TEST(SweptTest, TheEndPointTestTunnelsThroughFujiAndTheSweepStopsAtItsFlank) {
  const double summitLongitude = fujiSummit().longitudeRadians;
  for (const double length : {6000.0, 12000.0, 30000.0, 60000.0, 100000.0}) {
    const Crossing c = crossing(length);
    ASSERT_LT(drawn(c.west), kHeight - kClearance) << length;
    ASSERT_LT(drawn(c.east), kHeight - kClearance) << length;
    ASSERT_GT(drawn(fujiSummit()), kHeight + 300.0);
    const glm::dvec3 a = geo::cartographicToEcef(kWgs84, c.west);
    const glm::dvec3 b = geo::cartographicToEcef(kWgs84, c.east);

    // The paper tests where the camera ends: free, so the move passes under the summit.
    EXPECT_FALSE(probeSurface(fuji(), kWgs84, c.east, kClearance, SurfaceModel::Exact).collided);
    ResponseSettings endOnly;
    endOnly.sweep = false;
    const MotionResult tunnel = respondLinear(fuji(), kWgs84, c.west, b - a, kClearance, endOnly);
    ASSERT_TRUE(tunnel.valid);
    EXPECT_EQ(tunnel.response, Response::None);
    EXPECT_GT(tunnel.position.longitudeRadians, summitLongitude);

    // The sweep meets the west flank first.
    const SegmentSweep sweep =
        sweepSegment(fuji(), kWgs84, a, b, kClearance, SurfaceModel::Exact, {});
    ASSERT_TRUE(sweep.valid);
    ASSERT_TRUE(sweep.hit) << length;
    EXPECT_LT(sweep.freeFraction, 0.5);
    const auto free = *geo::ecefToCartographic(kWgs84, sweep.freeEcefMeters);
    EXPECT_LT(free.longitudeRadians, summitLongitude);
    EXPECT_GE(free.heightMeters - drawn(free), kClearance - 1e-6);
    EXPECT_LT(sweep.contact.heightMeters - drawn(sweep.contact), kClearance);
    const glm::dvec3 contact = geo::cartographicToEcef(kWgs84, sweep.contact);
    EXPECT_LT(glm::length(contact - sweep.freeEcefMeters), 2e-3);
    // Every metre of the way to the contact is free.
    const int n = static_cast<int>(glm::length(sweep.freeEcefMeters - a));
    double lowest = 1e9;
    for (int i = 0; i <= n; ++i) {
      const auto p =
          *geo::ecefToCartographic(kWgs84, a + (sweep.freeEcefMeters - a) * (double(i) / n));
      lowest = std::min(lowest, p.heightMeters - drawn(p));
    }
    EXPECT_GE(lowest, kClearance - 1e-3) << length;

    // The response stops there and slides on from it.
    const MotionResult slid = respondLinear(fuji(), kWgs84, c.west, b - a, kClearance, {});
    ASSERT_TRUE(slid.valid);
    EXPECT_EQ(slid.response, Response::Slid);
    EXPECT_NEAR(slid.firstContact.longitudeRadians, free.longitudeRadians, 1e-8);  // 6 cm: skin
    EXPECT_GE(slid.position.heightMeters - drawn(slid.position), kClearance - kContactSkinMeters);
    std::printf(
        "%6.0f m level move at %.0f m: end-point test ends %.0f m east of the summit; "
        "sweep stops %.0f m west of it after %u probes (%.1f m of path each), slide ends "
        "%.1f m above the surface\n",
        length, kHeight, glm::length(b - geo::cartographicToEcef(kWgs84, fujiSummit(kHeight))),
        glm::length(sweep.freeEcefMeters - geo::cartographicToEcef(kWgs84, fujiSummit(kHeight))),
        sweep.samples, length * sweep.freeFraction / sweep.samples,
        slid.position.heightMeters - drawn(slid.position));
  }
}

TEST(SweptTest, AnOrbitAcrossFujiIsLiftedOverTheSummit) {
  const Crossing c = crossing(12000.0);
  ResponseSettings endOnly;
  endOnly.sweep = false;
  const MotionResult tunnel = respondAngular(fuji(), kWgs84, c.west, c.east, kClearance, endOnly);
  ASSERT_TRUE(tunnel.valid);
  EXPECT_EQ(tunnel.response, Response::None);
  EXPECT_EQ(tunnel.position.heightMeters, kHeight);

  const ArcSweep arc =
      sweepArc(fuji(), kWgs84, c.west, c.east, kClearance, SurfaceModel::Exact, {});
  ASSERT_TRUE(arc.valid);
  // The lift carries the camera over the highest point of the arc's track (sampled every metre
  // here: the sweep, probing every grid line crossed, may find a higher one between them).
  double highest = 0.0;
  for (int i = 0; i <= 12000; ++i) {
    const geo::Cartographic p = arcPoint(kWgs84, c.west, c.east, i / 12000.0);
    highest = std::max(highest, drawn(p));
  }
  EXPECT_GT(arc.liftMeters, highest + kClearance - kHeight - 1e-3);
  EXPECT_LE(arc.liftMeters, highest + kClearance - kHeight + 0.5);  // the 1 m reference sampling
  const MotionResult lifted = respondAngular(fuji(), kWgs84, c.west, c.east, kClearance, {});
  EXPECT_EQ(lifted.response, Response::Heightened);
  EXPECT_EQ(lifted.position.longitudeRadians, c.east.longitudeRadians);
  EXPECT_EQ(lifted.position.latitudeRadians, c.east.latitudeRadians);
  EXPECT_GT(lifted.position.heightMeters, highest + kClearance - 1e-3);
  std::printf(
      "orbit across Fuji at %.0f m: track's highest surface %.1f m, lifted to %.1f m "
      "(%u probes)\n",
      kHeight, highest, lifted.position.heightMeters, arc.samples);
}

TEST(SweptTest, ArcPointsFollowTheRotationAndEndExactly) {
  const geo::Cartographic from = geo::Cartographic::fromDegrees(170.0, 80.0, 100.0);
  const geo::Cartographic to = geo::Cartographic::fromDegrees(-170.0, 85.0, 300.0);
  const geo::Cartographic start = arcPoint(kWgs84, from, to, 0.0);
  const geo::Cartographic end = arcPoint(kWgs84, from, to, 1.0);
  EXPECT_EQ(start.longitudeRadians, from.longitudeRadians);
  EXPECT_EQ(end.longitudeRadians, to.longitudeRadians);
  const geo::Cartographic middle = arcPoint(kWgs84, from, to, 0.5);
  EXPECT_DOUBLE_EQ(middle.heightMeters, 200.0);
  // Equal angles between consecutive normals.
  const auto normal = [](const geo::Cartographic& c) {
    return geo::geodeticSurfaceNormal(kWgs84, c);
  };
  const double a1 = std::acos(glm::dot(normal(from), normal(middle)));
  const double a2 = std::acos(glm::dot(normal(middle), normal(to)));
  EXPECT_NEAR(a1, a2, 1e-9);
  // Across the antimeridian the short way, not round the globe.
  EXPECT_GT(std::abs(middle.longitudeRadians), geo::degreesToRadians(170.0));
}

}  // namespace
}  // namespace globe::collision
