// Camera path interpolation: keys hit exactly, C1 smoothness, ±180°, the poles, shortest-arc
// orientation, monotone heights, holds and clamping.
#include "camera/camera_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>

#include "camera/camera_orientation.hpp"
#include "geo/ecef.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::camera {
namespace {

using globe::test::kWgs84;

CameraPath makePath(PathInterpolation interpolation,
                    std::initializer_list<std::pair<double, CameraPose>> keys) {
  CameraPath path;
  path.interpolation = interpolation;
  for (const auto& [t, pose] : keys) path.keyframes.push_back({t, pose});
  return path;
}

glm::dvec3 ecef(const CameraPose& pose) { return geo::cartographicToEcef(kWgs84, pose.position); }

double headingDegrees(const CameraPose& pose) {
  const double degrees = geo::radiansToDegrees(pose.headingRadians);
  return degrees < 0 ? degrees + 360 : degrees;
}

bool isFinite(const CameraPose& pose) { return pose.isFinite(); }

// A winding path with uneven key spacing: a turn, a climb, a descent and a roll.
CameraPath windingPath(PathInterpolation interpolation) {
  return makePath(interpolation,
                  {{0.0, CameraPose::fromDegrees(138.60, 35.20, 8000, 30, -30, 0)},
                   {2.0, CameraPose::fromDegrees(138.70, 35.34, 3000, 60, -20, 5)},
                   {2.5, CameraPose::fromDegrees(138.74, 35.36, 3500, 120, -10, 0)},
                   {6.0, CameraPose::fromDegrees(138.80, 35.30, 2000, 200, -45, -10)},
                   {7.0, CameraPose::fromDegrees(138.85, 35.20, 5000, 250, -80, 0)}});
}

// Keyframes above the terrain: the height above the ground is interpolated, so the path follows
// a ridge between them instead of cutting through it; a mixed segment changes over linearly.
TEST(CameraPath, HeightsAboveTheTerrainFollowItBetweenKeyframes) {
  // A 900 m ridge across the middle of the segment (a Gaussian in longitude).
  const TerrainHeightAt ridge = [](double lon, double) {
    const double x = (geo::radiansToDegrees(lon) - 8.45) / 0.01;
    return 100.0 + 800.0 * std::exp(-x * x);
  };
  for (const PathInterpolation interpolation :
       {PathInterpolation::Linear, PathInterpolation::Smooth}) {
    CameraPath path =
        makePath(interpolation, {{0.0, CameraPose::fromDegrees(8.40, 50.2, 150, 90, -5, 0)},
                                 {10.0, CameraPose::fromDegrees(8.50, 50.2, 150, 90, -5, 0)}});
    for (CameraKeyframe& key : path.keyframes) key.heightAboveTerrain = true;
    for (double t = 0; t <= 10.0; t += 0.25) {
      const CameraPose pose = samplePath(path, t, kWgs84, ridge);
      const double ground = ridge(pose.position.longitudeRadians, pose.position.latitudeRadians);
      EXPECT_NEAR(pose.position.heightMeters - ground, 150.0, 1e-6) << t;
    }
    // Without the terrain the stored heights are taken as they are (above the ellipsoid).
    EXPECT_NEAR(samplePath(path, 5.0, kWgs84).position.heightMeters, 150.0, 1e-6);
    // Absolute at the start, above the terrain at the end: the terrain's share grows linearly.
    path.keyframes[0].heightAboveTerrain = false;
    path.keyframes[0].pose.position.heightMeters = 1000.0;
    const CameraPose mid = samplePath(path, 5.0, kWgs84, ridge);
    const CameraPose stored = samplePath(path, 5.0, kWgs84);
    EXPECT_NEAR(mid.position.heightMeters - stored.position.heightMeters,
                0.5 * ridge(mid.position.longitudeRadians, mid.position.latitudeRadians), 1e-6);
    EXPECT_NEAR(samplePath(path, 0.0, kWgs84, ridge).position.heightMeters, 1000.0, 1e-9);
  }
}

TEST(CameraPath, KeyframesAreHitExactly) {
  for (const auto interpolation : {PathInterpolation::Linear, PathInterpolation::Smooth}) {
    const CameraPath path = windingPath(interpolation);
    for (const CameraKeyframe& key : path.keyframes) {
      const CameraPose pose = samplePath(path, key.timeSeconds, kWgs84);
      EXPECT_EQ(pose.position.longitudeRadians, key.pose.position.longitudeRadians);
      EXPECT_EQ(pose.position.latitudeRadians, key.pose.position.latitudeRadians);
      EXPECT_EQ(pose.position.heightMeters, key.pose.position.heightMeters);
      EXPECT_EQ(pose.headingRadians, key.pose.headingRadians);
      EXPECT_EQ(pose.pitchRadians, key.pose.pitchRadians);
      EXPECT_EQ(pose.rollRadians, key.pose.rollRadians);
    }
    // Just off a key, the decoded pose is the key's to ~1e-9 (the ECEF round trip is exact).
    for (const CameraKeyframe& key : path.keyframes) {
      const double t = key.timeSeconds + (key.timeSeconds < 7 ? 1e-9 : -1e-9);
      const CameraPose near = samplePath(path, t, kWgs84);
      EXPECT_LT(glm::length(ecef(near) - ecef(key.pose)), 1e-3);
      EXPECT_NEAR(
          std::remainder(near.headingRadians - key.pose.headingRadians, 2 * std::numbers::pi), 0,
          1e-6);
      EXPECT_NEAR(near.pitchRadians, key.pose.pitchRadians, 1e-6);
      EXPECT_NEAR(near.rollRadians, key.pose.rollRadians, 1e-6);
    }
  }
}

TEST(CameraPath, ClampsBeforeTheStartAndAfterTheEnd) {
  const CameraPath path = windingPath(PathInterpolation::Smooth);
  EXPECT_EQ(samplePath(path, -5, kWgs84).position.heightMeters, 8000);
  EXPECT_EQ(samplePath(path, 100, kWgs84).position.heightMeters, 5000);
  EXPECT_EQ(samplePath(path, std::nan(""), kWgs84).position.heightMeters, 8000);
  EXPECT_EQ(samplePath(CameraPath{}, 1, kWgs84).position.heightMeters, 0);  // empty: a default
  const CameraPath one = makePath(PathInterpolation::Smooth,
                                  {{3.0, CameraPose::fromDegrees(10, 20, 300, 40, -50, 0)}});
  EXPECT_EQ(samplePath(one, 0, kWgs84).position.heightMeters, 300);
  EXPECT_EQ(samplePath(one, 9, kWgs84).position.heightMeters, 300);
}

TEST(CameraPath, NonFiniteAndHugeTimesGiveAnEndKeyAndHugeKeysStayFinite) {
  const CameraPath path = windingPath(PathInterpolation::Smooth);
  const double kMax = std::numeric_limits<double>::max();
  const double kInf = std::numeric_limits<double>::infinity();
  const std::pair<double, double> timesAndHeights[] = {
      {std::nan(""), 8000}, {-kInf, 8000}, {-kMax, 8000}, {-1e300, 8000},
      {kInf, 5000},         {kMax, 5000},  {1e300, 5000},
  };
  for (const auto& [time, height] : timesAndHeights) {
    const CameraPose pose = samplePath(path, time, kWgs84);
    EXPECT_TRUE(isFinite(pose)) << time;
    EXPECT_EQ(pose.position.heightMeters, height) << time;
  }
  // Keys whose time span overflows a double, with huge angles: every sample is finite.
  for (const PathInterpolation interpolation :
       {PathInterpolation::Smooth, PathInterpolation::Linear}) {
    const CameraPath wide = makePath(
        interpolation, {{-kMax, CameraPose::fromDegrees(138.6, 35.2, 8000, 1e300, -30)},
                        {0.0, CameraPose::fromDegrees(138.7, 35.3, 3000, -1e300, -20)},
                        {kMax, CameraPose::fromDegrees(138.8, 35.4, 4000e4, 0, 90, 1e300)}});
    for (const double time : {-kMax, -1e308, -1.0, 0.0, 1e-300, 1e300, kMax}) {
      EXPECT_TRUE(isFinite(samplePath(wide, time, kWgs84))) << time;
    }
  }
}

// Velocity estimates from either side of t: equal for a C1 path, different at a corner.
struct SideVelocities {
  glm::dvec3 position[2];
  glm::dvec3 forward[2];
};
SideVelocities velocitiesAround(const CameraPath& path, double t, double h) {
  auto at = [&](double time) { return samplePath(path, time, kWgs84); };
  auto fwd = [&](double time) { return cameraFrame(kWgs84, at(time)).forward; };
  SideVelocities v;
  // Second-order one-sided differences: exact for quadratics, so a cubic's error is O(h^2).
  v.position[0] = (3.0 * ecef(at(t)) - 4.0 * ecef(at(t - h)) + ecef(at(t - 2 * h))) / (2 * h);
  v.position[1] = (-3.0 * ecef(at(t)) + 4.0 * ecef(at(t + h)) - ecef(at(t + 2 * h))) / (2 * h);
  v.forward[0] = (3.0 * fwd(t) - 4.0 * fwd(t - h) + fwd(t - 2 * h)) / (2 * h);
  v.forward[1] = (-3.0 * fwd(t) + 4.0 * fwd(t + h) - fwd(t + 2 * h)) / (2 * h);
  return v;
}

// The Sun's instant along a path: linear between the keyframes that carry one, held before the
// first and after the last, none when no keyframe has one.
TEST(CameraPath, SunTimesAreInterpolatedBetweenTheKeyframesThatHaveThem) {
  CameraPath path;
  const CameraPose pose = CameraPose::fromDegrees(0, 0, 1000, 0, -90, 0);
  path.keyframes = {{0, pose, false, std::nullopt},
                    {10, pose, false, 1000.0},
                    {20, pose, false, std::nullopt},
                    {30, pose, false, 5000.0}};
  EXPECT_EQ(sampleSunTime(path, -5), 1000.0);
  EXPECT_EQ(sampleSunTime(path, 0), 1000.0);
  EXPECT_EQ(sampleSunTime(path, 10), 1000.0);
  EXPECT_EQ(sampleSunTime(path, 20), 3000.0) << "keyframes without a time do not stop it";
  EXPECT_EQ(sampleSunTime(path, 25), 4000.0);
  EXPECT_EQ(sampleSunTime(path, 30), 5000.0);
  EXPECT_EQ(sampleSunTime(path, 99), 5000.0);
  path.keyframes[1].sunUnixSeconds.reset();
  path.keyframes[3].sunUnixSeconds.reset();
  EXPECT_FALSE(sampleSunTime(path, 15));
}

TEST(CameraPath, SmoothIsC1AtEveryKeyAndLinearIsNot) {
  const CameraPath smooth = windingPath(PathInterpolation::Smooth);
  const CameraPath linear = windingPath(PathInterpolation::Linear);
  for (const double t : {2.0, 2.5, 6.0}) {
    const SideVelocities s = velocitiesAround(smooth, t, 1e-4);
    const double speed = glm::length(s.position[1]);
    EXPECT_GT(speed, 100.0) << t;  // it moves through the key (m/s)
    EXPECT_LT(glm::length(s.position[0] - s.position[1]), 1e-3 * speed) << t;
    const double turn = glm::length(s.forward[1]);
    EXPECT_GT(turn, 1e-3) << t;  // and turns (rad/s)
    EXPECT_LT(glm::length(s.forward[0] - s.forward[1]), 1e-3 * turn) << t;
    const SideVelocities l = velocitiesAround(linear, t, 1e-4);
    EXPECT_GT(glm::length(l.position[0] - l.position[1]), 0.05 * glm::length(l.position[1])) << t;
  }
  // Starts and ends at rest.
  EXPECT_LT(glm::length(velocitiesAround(smooth, 7.0, 1e-4).position[0]), 1e-2);
  // On a fine grid the velocity never jumps (~9 km/s along this path, accelerating at up to
  // ~25 km/s^2); the linear path's does, at every key.
  auto largestVelocityStep = [](const CameraPath& path) {
    double largest = 0;
    glm::dvec3 previous = velocitiesAround(path, 0.01, 1e-4).position[1];
    for (double t = 0.02; t < 6.99; t += 0.01) {
      const glm::dvec3 v = velocitiesAround(path, t, 1e-4).position[1];
      largest = std::max(largest, glm::length(v - previous));
      previous = v;
    }
    return largest;
  };
  EXPECT_LT(largestVelocityStep(smooth), 700.0);
  EXPECT_GT(largestVelocityStep(linear), 5000.0);
  std::printf("largest velocity step in 0.01 s: smooth %.0f m/s, linear %.0f m/s\n",
              largestVelocityStep(smooth), largestVelocityStep(linear));
}

TEST(CameraPath, CrossingTheAntimeridianGoesTheShortWay) {
  for (const auto interpolation : {PathInterpolation::Linear, PathInterpolation::Smooth}) {
    const CameraPath path =
        makePath(interpolation, {{0, CameraPose::fromDegrees(179.0, 10, 500, 90, -30, 0)},
                                 {1, CameraPose::fromDegrees(-179.5, 10.2, 500, 90, -30, 0)},
                                 {2, CameraPose::fromDegrees(-179.0, 10.4, 500, 90, -30, 0)}});
    bool crossed = false;
    for (double t = 0; t <= 2.0; t += 0.01) {
      const CameraPose pose = samplePath(path, t, kWgs84);
      ASSERT_TRUE(isFinite(pose));
      EXPECT_GE(std::abs(pose.position.longitudeDegrees()), 178.99) << t;  // never via 0°
      EXPECT_NEAR(headingDegrees(pose), 90, 0.5) << t;
      crossed = crossed || (t > 0.1 && pose.position.longitudeDegrees() < 0);
    }
    EXPECT_TRUE(crossed);
    EXPECT_NEAR(samplePath(path, 0.5, kWgs84).position.heightMeters, 500, 1e-6);
  }
}

TEST(CameraPath, OverThePoleNoNanAndItPassesThePole) {
  for (const auto interpolation : {PathInterpolation::Linear, PathInterpolation::Smooth}) {
    // 85°N at 0° to 85°N at 180°: the great circle runs over the pole.
    const CameraPath path =
        makePath(interpolation, {{0, CameraPose::fromDegrees(0, 85, 1000, 0, -20, 0)},
                                 {4, CameraPose::fromDegrees(180, 85, 1000, 180, -20, 0)},
                                 {5, CameraPose::fromDegrees(180, 80, 1000, 180, -20, 0)}});
    double highest = 0;
    glm::dvec3 previousForward = cameraFrame(kWgs84, path.keyframes[0].pose).forward;
    for (double t = 0; t <= 5.0; t += 0.001) {
      const CameraPose pose = samplePath(path, t, kWgs84);
      ASSERT_TRUE(isFinite(pose)) << t;
      highest = std::max(highest, pose.position.latitudeDegrees());
      EXPECT_NEAR(pose.position.heightMeters, 1000, 1e-6) << t;
      // The view turns smoothly through the pole: no flip of the forward vector.
      const glm::dvec3 forward = cameraFrame(kWgs84, pose).forward;
      EXPECT_LT(glm::length(forward - previousForward), 0.002) << t;
      previousForward = forward;
    }
    EXPECT_GT(highest, 89.999);
    // Exactly at the pole (t = 2 by symmetry for linear): finite, the pole itself.
    const CameraPose atPole = samplePath(path, 2.0, kWgs84);
    ASSERT_TRUE(isFinite(atPole));
    if (interpolation == PathInterpolation::Linear) {
      EXPECT_NEAR(atPole.position.latitudeDegrees(), 90, 1e-9);
    }
  }
  // A keyframe exactly at the pole.
  const CameraPath viaPole =
      makePath(PathInterpolation::Smooth, {{0, CameraPose::fromDegrees(45, 88, 500, 0, -90, 0)},
                                           {1, CameraPose::fromDegrees(0, 90, 500, 0, -90, 0)},
                                           {2, CameraPose::fromDegrees(-135, 88, 500, 0, -90, 0)}});
  for (double t = 0; t <= 2.0; t += 0.01) ASSERT_TRUE(isFinite(samplePath(viaPole, t, kWgs84)));
}

TEST(CameraPath, OrientationTakesTheShortestArc) {
  for (const auto interpolation : {PathInterpolation::Linear, PathInterpolation::Smooth}) {
    const CameraPath path =
        makePath(interpolation, {{0, CameraPose::fromDegrees(10, 45, 2000, 350, -30, 0)},
                                 {1, CameraPose::fromDegrees(10, 45, 2000, 10, -30, 0)}});
    for (double t = 0; t <= 1.0; t += 0.02) {
      const double heading = headingDegrees(samplePath(path, t, kWgs84));
      EXPECT_TRUE(heading >= 349.999 || heading <= 10.001) << t << ": " << heading;
    }
    EXPECT_NEAR(std::remainder(headingDegrees(samplePath(path, 0.5, kWgs84)), 360.0), 0, 1e-6);
    EXPECT_NEAR(geo::radiansToDegrees(samplePath(path, 0.5, kWgs84).pitchRadians), -30, 1e-6);
  }
  // Roll from 170° to -170° goes through 180°, not through 0°.
  const CameraPath roll =
      makePath(PathInterpolation::Linear, {{0, CameraPose::fromDegrees(0, 0, 100, 0, 0, 170)},
                                           {1, CameraPose::fromDegrees(0, 0, 100, 0, 0, -170)}});
  EXPECT_NEAR(std::abs(geo::radiansToDegrees(samplePath(roll, 0.5, kWgs84).rollRadians)), 180,
              1e-6);
}

TEST(CameraPath, SmoothHeightsNeverOvershootTheirKeys) {
  const CameraPath path =
      makePath(PathInterpolation::Smooth, {{0, CameraPose::fromDegrees(0, 0, 5000, 0, -30, 0)},
                                           {1, CameraPose::fromDegrees(0.01, 0, 100, 0, -30, 0)},
                                           {1.2, CameraPose::fromDegrees(0.02, 0, 5000, 0, -30, 0)},
                                           {5, CameraPose::fromDegrees(0.03, 0, 6000, 0, -30, 0)}});
  for (double t = 0; t <= 5; t += 0.001) {
    const double h = samplePath(path, t, kWgs84).position.heightMeters;
    EXPECT_GE(h, 100 - 1e-9) << t;
    EXPECT_LE(h, 6000 + 1e-9) << t;
  }
}

TEST(CameraPath, AShortSlowSegmentBesideALongFastOneDoesNotSwingOut) {
  // 100 m in 1 s, then 4,000 km in 1 s: Catmull-Rom would swing hundreds of km out.
  const CameraPath path = makePath(
      PathInterpolation::Smooth, {{0, CameraPose::fromDegrees(138.7300, 35.362, 3600, 60, -20, 0)},
                                  {1, CameraPose::fromDegrees(138.7310, 35.362, 3600, 60, -20, 0)},
                                  {2, CameraPose::fromDegrees(150.0, -0.0, 2e6, 60, -20, 0)}});
  const glm::dvec3 a = ecef(path.keyframes[0].pose), b = ecef(path.keyframes[1].pose);
  for (double t = 0; t <= 1.0; t += 0.01) {
    const glm::dvec3 p = ecef(samplePath(path, t, kWgs84));
    EXPECT_LT(glm::length(p - a), 1.5 * glm::length(b - a)) << t;
    EXPECT_LT(glm::length(p - b), 1.5 * glm::length(b - a)) << t;
  }
}

TEST(CameraPath, ARepeatedKeyframeHoldsStill) {
  const CameraPose hold = CameraPose::fromDegrees(5, 5, 700, 45, -20, 0);
  const CameraPath path =
      makePath(PathInterpolation::Smooth, {{0, CameraPose::fromDegrees(4, 4, 900, 10, -40, 0)},
                                           {1, hold},
                                           {3, hold},
                                           {4, CameraPose::fromDegrees(6, 6, 500, 90, -10, 0)}});
  for (double t = 1.0; t <= 3.0; t += 0.05) {
    const CameraPose pose = samplePath(path, t, kWgs84);
    EXPECT_LT(glm::length(ecef(pose) - ecef(hold)), 1e-6) << t;
    EXPECT_NEAR(pose.headingRadians, hold.headingRadians, 1e-9) << t;
  }
}

TEST(CameraOrientation, RoundTripsPosesAndLogExpAreInverse) {
  for (const CameraPose& pose : {CameraPose::fromDegrees(10, 20, 100, 30, -40, 15),
                                 CameraPose::fromDegrees(-170, -60, 5, 300, 10, -30),
                                 CameraPose::fromDegrees(0, 90, 50, 0, -45, 0)}) {
    const CameraPose back =
        poseFromOrientation(kWgs84, pose.position, orientationEcef(kWgs84, pose));
    const CameraFrame a = cameraFrame(kWgs84, pose), b = cameraFrame(kWgs84, back);
    EXPECT_LT(glm::length(a.forward - b.forward), 1e-12);
    EXPECT_LT(glm::length(a.up - b.up), 1e-12);
  }
  // Straight down: the roll folds into the heading, the frame is the same.
  const CameraPose down = CameraPose::fromDegrees(10, 20, 100, 30, -90, 20);
  const CameraPose back = poseFromOrientation(kWgs84, down.position, orientationEcef(kWgs84, down));
  EXPECT_LT(glm::length(cameraFrame(kWgs84, down).up - cameraFrame(kWgs84, back).up), 1e-9);
  const glm::dvec3 r(0.3, -0.2, 1.1);
  EXPECT_LT(glm::length(logRotation(expRotation(r)) - r), 1e-12);
  EXPECT_NEAR(glm::length(logRotation(expRotation(glm::dvec3(0, 0, 3.5)))),
              2 * std::numbers::pi - 3.5,
              1e-12);  // the shortest arc
}

}  // namespace
}  // namespace globe::camera
