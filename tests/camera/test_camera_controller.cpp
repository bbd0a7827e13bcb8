// The controller on Fuji's real surface: jumps stopped, proposals classified, slides, heightening
// with the angle exact, accelerations like velocities, non-finite input rejected.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>

#include "camera/camera_controller.hpp"
#include "geo/ecef.hpp"
#include "tests/camera/controller_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::camera {
namespace {

using collision::Response;
using globe::test::kDt;
using testing::drawnHeight;
using testing::fujiSummit;
using testing::offsetPosition;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
using globe::test::kWgs84;

using testing::drawn;
using testing::fuji;

geo::Cartographic onSlope(double bearingRadians, double distanceMeters, double aboveMeters) {
  geo::Cartographic c = offsetPosition(fujiSummit(), bearingRadians, distanceMeters, 0.0);
  c.heightMeters = drawn(c) + aboveMeters;
  return c;
}

void expectSamePose(const CameraPose& a, const CameraPose& b) {
  EXPECT_EQ(a.position.longitudeRadians, b.position.longitudeRadians);
  EXPECT_EQ(a.position.latitudeRadians, b.position.latitudeRadians);
  EXPECT_EQ(a.position.heightMeters, b.position.heightMeters);
  EXPECT_EQ(a.headingRadians, b.headingRadians);
  EXPECT_EQ(a.pitchRadians, b.pitchRadians);
  EXPECT_EQ(a.rollRadians, b.rollRadians);
}

double distanceToSummit(const geo::Cartographic& c) {
  geo::Cartographic ground = c;
  ground.heightMeters = 0.0;
  return glm::length(geo::cartographicToEcef(kWgs84, ground) -
                     geo::cartographicToEcef(kWgs84, fujiSummit()));
}

TEST(CameraController, AStaticCameraJumpingIntoFujiIsStoppedAndKeepsItsPose) {
  const CameraPose start{fujiSummit(drawn(fujiSummit()) + 800.0), 0.3, -0.5, 0.0};
  CameraController controller(start);
  controller.update(kDt, fuji(), kWgs84);
  const CameraPose valid = controller.pose();
  ASSERT_TRUE(controller.setTargetPose({onSlope(0.7, 1500.0, -20.0), 1.0, 0.2, 0.1}));
  const CollisionState& state = controller.update(kDt, fuji(), kWgs84);
  EXPECT_TRUE(state.collided);
  EXPECT_EQ(state.response, Response::Stopped);
  EXPECT_EQ(state.motion, MotionKind::Jump);
  expectSamePose(controller.pose(), valid);
  // The same jump 10 m above the surface is made, orientation included.
  const CameraPose above{onSlope(0.7, 1500.0, 10.0), 1.0, -0.2, 0.1};
  ASSERT_TRUE(controller.setTargetPose(above));
  EXPECT_EQ(controller.update(kDt, fuji(), kWgs84).response, Response::None);
  EXPECT_DOUBLE_EQ(controller.pose().position.heightMeters, above.position.heightMeters);
  EXPECT_EQ(controller.pose().headingRadians, above.headingRadians);
}

TEST(CameraController, ProposalsAreClassifiedAndAnsweredByTheirKind) {
  const geo::Cartographic here = onSlope(std::numbers::pi / 2, 3000.0, 2.0);
  CameraController controller({here, -std::numbers::pi / 2, 0.0, 0.0});
  controller.update(kDt, fuji(), kWgs84);
  // Same height, 100 m towards the summit: an angular move, heightened onto the slope.
  geo::Cartographic west = offsetPosition(here, 1.5 * std::numbers::pi, 100.0, here.heightMeters);
  ASSERT_TRUE(controller.propose({west, -std::numbers::pi / 2, 0.0, 0.0}));
  CollisionState state = controller.update(kDt, fuji(), kWgs84);
  EXPECT_EQ(state.motion, MotionKind::Angular);
  EXPECT_EQ(state.response, Response::Heightened);
  EXPECT_NEAR(controller.pose().position.longitudeRadians, west.longitudeRadians, 1e-15);
  EXPECT_NEAR(controller.pose().position.latitudeRadians, west.latitudeRadians, 1e-15);
  EXPECT_GE(state.clearanceMeters, 2.0 - 1e-9);
  // A move with a height change: linear, slides.
  const geo::Cartographic from = controller.pose().position;
  geo::Cartographic lower =
      offsetPosition(from, 1.5 * std::numbers::pi, 100.0, from.heightMeters - 5.0);
  ASSERT_TRUE(controller.propose({lower, -std::numbers::pi / 2, 0.0, 0.0}));
  state = controller.update(kDt, fuji(), kWgs84);
  EXPECT_EQ(state.motion, MotionKind::Linear);
  EXPECT_EQ(state.response, Response::Slid);
  EXPECT_GE(state.clearanceMeters, 2.0 - 1e-9);
  EXPECT_LT(distanceToSummit(controller.pose().position), distanceToSummit(from));
  // A move farther than jumpDistanceMeters is a jump: into the mountain, refused.
  const CameraPose before = controller.pose();
  ASSERT_TRUE(controller.propose({offsetPosition(fujiSummit(), 0.0, 10.0, 3000.0), 0, 0, 0}));
  ControllerSettings settings = controller.settings();
  EXPECT_EQ(
      classifyMotion(kWgs84, before.position, fujiSummit(3000.0), settings.jumpDistanceMeters),
      MotionKind::Linear);
  EXPECT_EQ(classifyMotion(kWgs84, before.position, fujiSummit(3000.0), 1000.0), MotionKind::Jump);
  state = controller.update(kDt, fuji(), kWgs84);
  EXPECT_EQ(state.motion, MotionKind::Linear);  // 3 km < 1000 km: a (fast) linear move
  // An orientation change alone is a (static) jump, made at once.
  CameraPose turned = controller.pose();
  turned.headingRadians += 1.0;
  ASSERT_TRUE(controller.propose(turned));
  state = controller.update(kDt, fuji(), kWgs84);
  EXPECT_EQ(state.motion, MotionKind::Jump);
  EXPECT_EQ(controller.pose().headingRadians, turned.headingRadians);
  EXPECT_EQ(controller.pose().position.heightMeters, turned.position.heightMeters);
}

TEST(CameraController, ClassificationOfMoves) {
  const geo::Cartographic a = geo::Cartographic::fromDegrees(180.0, 10.0, 100.0);
  const geo::Cartographic b = geo::Cartographic::fromDegrees(-180.0, 10.0, 100.0);
  EXPECT_TRUE(isSamePosition(kWgs84, a, b));
  EXPECT_EQ(classifyMotion(kWgs84, a, b, 1e6), MotionKind::Jump);
  const geo::Cartographic east = geo::Cartographic::fromDegrees(-179.9, 10.0, 100.0);
  EXPECT_EQ(classifyMotion(kWgs84, a, east, 1e6), MotionKind::Angular);
  EXPECT_EQ(classifyMotion(kWgs84, a, {east.longitudeRadians, east.latitudeRadians, 90.0}, 1e6),
            MotionKind::Linear);
  EXPECT_EQ(classifyMotion(kWgs84, a, east, 1000.0), MotionKind::Jump);  // 11 km > 1 km
  const geo::Cartographic northPole{0.3, std::numbers::pi / 2, 5.0};
  EXPECT_TRUE(isSamePosition(kWgs84, northPole, {-2.0, std::numbers::pi / 2, 5.0}));
}

TEST(CameraController, LinearVelocitySlidesUpTheSlopeFrameAfterFrame) {
  for (const double bearing :
       {0.0, std::numbers::pi / 2, std::numbers::pi, 1.5 * std::numbers::pi}) {
    const geo::Cartographic start = onSlope(bearing, 3000.0, 2.0);
    CameraController controller({start, bearing + std::numbers::pi, 0.0, 0.0});
    ASSERT_TRUE(
        controller.setVelocity(30.0 * testing::direction(start, bearing + std::numbers::pi, 0.0)));
    const glm::dvec3 velocity = controller.velocity();
    int slid = 0;
    double lowest = kInf;
    for (int frame = 0; frame < 150; ++frame) {
      const CollisionState& state = controller.update(kDt, fuji(), kWgs84);
      slid += state.response == Response::Slid;
      lowest = std::min(lowest, state.clearanceMeters);
    }
    const geo::Cartographic end = controller.pose().position;
    const double progress = distanceToSummit(start) - distanceToSummit(end);
    std::printf(
        "bearing %3.0f: 150 frames at 1 m/frame, %d slid, %.1f m nearer the summit, "
        "%.1f m higher, lowest clearance %.3f m\n",
        bearing * 180 / std::numbers::pi, slid, progress, end.heightMeters - start.heightMeters,
        lowest);
    EXPECT_GT(slid, 50);
    EXPECT_GT(progress, 40.0);                                         // tangential progress
    EXPECT_GT(end.heightMeters - start.heightMeters, 0.1 * progress);  // up the slope
    EXPECT_GE(lowest, 2.0 - 1e-9);                                     // never below
    EXPECT_EQ(controller.velocity(), velocity);  // the response leaves the velocity alone
  }
}

TEST(CameraController, AngularVelocityIsHeightenedWithoutChangingIt) {
  for (const bool sweep : {false, true}) {
    for (const double bearing : {std::numbers::pi / 2, 1.5 * std::numbers::pi}) {
      const geo::Cartographic start = onSlope(bearing, 3000.0, 2.0);
      ControllerSettings settings;
      settings.response.sweep = sweep;
      CameraController controller({start, bearing + std::numbers::pi, 0.0, 0.0}, settings);
      const glm::dvec3 p = geo::cartographicToEcef(kWgs84, start);
      const double rate =
          (bearing < std::numbers::pi ? -1.0 : 1.0) * 30.0 / std::hypot(p.x, p.y) / kDt;
      const glm::dvec3 omega(0.0, 0.0, rate);  // about the polar axis, towards the summit
      ASSERT_TRUE(controller.setAngularVelocity(omega));
      int heightened = 0;
      double previousLongitude = start.longitudeRadians;
      for (int frame = 0; frame < 90; ++frame) {
        const CollisionState& state = controller.update(kDt, fuji(), kWgs84);
        const geo::Cartographic& now = controller.pose().position;
        heightened += state.response == Response::Heightened;
        // The angular position advances exactly as the angular velocity says.
        EXPECT_NEAR(now.longitudeRadians - previousLongitude, rate * kDt, 1e-14);
        EXPECT_NEAR(now.latitudeRadians, start.latitudeRadians, 1e-14);
        EXPECT_GE(state.clearanceMeters, 2.0 - 1e-9);
        if (state.response == Response::Heightened) {
          // Raised to the surface + clearance; with the sweep, over the highest point of the
          // frame's arc (a crater rim crossed leaves it higher above the floor beyond).
          if (sweep) {
            EXPECT_GE(state.clearanceMeters, 2.0 - 1e-9);
          } else {
            // (unless the near plane pushed it further: SRTM voids drawn at 0 m make pits with
            // walls of ~40:1 on Fuji's flanks, see NearPlane tests)
            if (!state.nearPlanePushed) {
              EXPECT_NEAR(state.clearanceMeters, 2.0 + collision::kContactSkinMeters, 1e-9);
            }
          }
        }
        previousLongitude = now.longitudeRadians;
      }
      EXPECT_GT(heightened, 20);
      EXPECT_EQ(controller.angularVelocity(), omega);
      const double climbed = controller.pose().position.heightMeters - start.heightMeters;
      std::printf(
          "orbit towards the summit from %3.0f deg, sweep %d: 90 frames at 30 m, "
          "%d heightened, %.1f m higher\n",
          bearing * 180 / std::numbers::pi, sweep, heightened, climbed);
      EXPECT_GT(climbed, 100.0);
    }
  }
}

TEST(CameraController, AccelerationsAreTreatedLikeVelocities) {
  const geo::Cartographic start = onSlope(std::numbers::pi, 3000.0, 2.0);
  CameraController controller({start, 0.0, 0.0, 0.0});
  const glm::dvec3 a = 20.0 * testing::direction(start, 0.0, 0.0);
  ASSERT_TRUE(controller.setAcceleration(a));
  int slid = 0;
  for (int frame = 1; frame <= 90; ++frame) {
    const CollisionState& state = controller.update(kDt, fuji(), kWgs84);
    slid += state.response == Response::Slid;
    EXPECT_GE(state.clearanceMeters, 2.0 - 1e-9);
    EXPECT_NEAR(glm::length(controller.velocity() - a * (frame * kDt)), 0.0, 1e-9);
  }
  EXPECT_GT(slid, 30);
  EXPECT_LT(distanceToSummit(controller.pose().position), distanceToSummit(start) - 50.0);

  // Angular acceleration about the polar axis, into the east flank: heightened.
  const geo::Cartographic east = onSlope(std::numbers::pi / 2, 3000.0, 2.0);
  CameraController orbit({east, -std::numbers::pi / 2, 0.0, 0.0});
  ASSERT_TRUE(orbit.setAngularAcceleration({0.0, 0.0, -2e-6}));
  int heightened = 0;
  for (int frame = 1; frame <= 90; ++frame) {
    const CollisionState& state = orbit.update(kDt, fuji(), kWgs84);
    heightened += state.response == Response::Heightened;
    EXPECT_GE(state.clearanceMeters, 2.0 - 1e-9);
  }
  EXPECT_GT(heightened, 10);
  EXPECT_NEAR(orbit.angularVelocity().z, -2e-6 * 90 * kDt, 1e-15);
  // The angle turned is the integral of the angular velocity: -a t^2 / 2.
  EXPECT_NEAR(orbit.pose().position.longitudeRadians - east.longitudeRadians,
              -0.5 * 2e-6 * (3.0 * 3.0), 1e-12);
}

TEST(CameraController, NonFiniteInputIsRejectedAndTheLastValidPoseKept) {
  const CameraPose start{onSlope(0.3, 2000.0, 20.0), 0.5, -0.3, 0.0};
  CameraController controller(start);
  controller.update(kDt, fuji(), kWgs84);
  const CameraPose valid = controller.pose();
  const CameraPose bad[] = {
      {{kNan, start.position.latitudeRadians, 3000.0}, 0, 0, 0},
      {{start.position.longitudeRadians, kInf, 3000.0}, 0, 0, 0},
      {{start.position.longitudeRadians, start.position.latitudeRadians, -kInf}, 0, 0, 0},
      {start.position, kNan, 0, 0},
      {start.position, 0, 0, kInf},
      {{start.position.longitudeRadians, 2.0, 3000.0}, 0, 0, 0},  // |latitude| > 90 deg
  };
  for (const CameraPose& pose : bad) {
    EXPECT_FALSE(controller.propose(pose));
    EXPECT_FALSE(controller.setTargetPose(pose));
    const CollisionState& state = controller.update(kDt, fuji(), kWgs84);
    EXPECT_TRUE(state.inputRejected);
    expectSamePose(controller.pose(), valid);
  }
  EXPECT_FALSE(controller.setVelocity({kNan, 0, 0}));
  EXPECT_FALSE(controller.setAcceleration({0, kInf, 0}));
  EXPECT_FALSE(controller.setAngularVelocity({0, 0, kNan}));
  EXPECT_FALSE(controller.setAngularAcceleration({-kInf, 0, 0}));
  EXPECT_FALSE(controller.setNearPlane({kNan, 0.7, 1.5}));
  EXPECT_EQ(controller.velocity(), glm::dvec3(0.0));
  EXPECT_TRUE(controller.update(kDt, fuji(), kWgs84).inputRejected);
  expectSamePose(controller.pose(), valid);
  for (const double dt : {kNan, kInf, -1.0}) {
    EXPECT_TRUE(controller.update(dt, fuji(), kWgs84).inputRejected);
    expectSamePose(controller.pose(), valid);
  }
  // A finite velocity whose motion overflows: the motion is refused, the pose kept.
  ASSERT_TRUE(controller.setVelocity({1e300, 1e300, 0.0}));
  EXPECT_TRUE(controller.update(kDt, fuji(), kWgs84).inputRejected);
  expectSamePose(controller.pose(), valid);
  // A huge angular velocity still gives a finite pose above the surface.
  controller.stop();
  ASSERT_TRUE(controller.setAngularVelocity({1e300, 0.0, 0.0}));
  const CollisionState& state = controller.update(kDt, fuji(), kWgs84);
  EXPECT_TRUE(controller.pose().isFinite());
  EXPECT_GE(state.clearanceMeters, 2.0 - 1e-9);
  // A valid update after all that reports nothing rejected.
  controller.stop();
  EXPECT_FALSE(controller.update(kDt, fuji(), kWgs84).inputRejected);
  // A non-finite initial pose is replaced, and reported.
  CameraController fallback({{kNan, 0, 0}, 0, 0, 0});
  EXPECT_TRUE(fallback.pose().isFinite());
  EXPECT_TRUE(fallback.update(kDt, fuji(), kWgs84).inputRejected);
  EXPECT_FALSE(fallback.update(kDt, fuji(), kWgs84).inputRejected);
}

// A camera in motion that receives non-finite input in any form: the input is dropped and the
// camera goes on exactly as a twin that never received it (a bad dt moves nothing: the last
// valid pose is kept); a camera driven by proposals keeps its last valid pose for the frame.
TEST(CameraController, ARunningCameraDropsNonFiniteInputAndGoesOn) {
  struct BadInput {
    const char* name;
    std::function<void(CameraController&)> apply;
    double dtSeconds;
  };
  const geo::Cartographic at = onSlope(0.5, 2500.0, 300.0);
  const BadInput inputs[] = {
      {"propose NaN longitude",
       [&](CameraController& c) {
         c.propose({{kNan, at.latitudeRadians, 3000.0}, 0, 0, 0});
       },
       kDt},
      {"propose +inf height",
       [&](CameraController& c) {
         c.propose({{at.longitudeRadians, at.latitudeRadians, kInf}, 0, 0, 0});
       },
       kDt},
      {"propose -inf pitch",
       [&](CameraController& c) {
         c.propose({at, 0, -kInf, 0});
       },
       kDt},
      {"jump to NaN roll",
       [&](CameraController& c) {
         c.setTargetPose({at, 0, 0, kNan});
       },
       kDt},
      {"NaN velocity",
       [](CameraController& c) {
         c.setVelocity({0, kNan, 0});
       },
       kDt},
      {"inf acceleration",
       [](CameraController& c) {
         c.setAcceleration({kInf, 0, 0});
       },
       kDt},
      {"NaN angular velocity",
       [](CameraController& c) {
         c.setAngularVelocity({kNan, kNan, kNan});
       },
       kDt},
      {"-inf angular acceleration",
       [](CameraController& c) {
         c.setAngularAcceleration({0, 0, -kInf});
       },
       kDt},
      {"NaN near plane",
       [](CameraController& c) {
         c.setNearPlane({0.5, kNan, 1.7});
       },
       kDt},
      {"NaN dt", [](CameraController&) {}, kNan},
      {"+inf dt", [](CameraController&) {}, kInf},
      {"-inf dt", [](CameraController&) {}, -kInf},
  };
  for (const BadInput& input : inputs) {
    SCOPED_TRACE(input.name);
    CameraController controller({at, 0.3, -0.2, 0.0}), twin({at, 0.3, -0.2, 0.0});
    for (CameraController* c : {&controller, &twin}) {
      ASSERT_TRUE(c->setVelocity({20.0, -10.0, 5.0}));  // moving at 23 m/s
      for (int frame = 0; frame < 5; ++frame) c->update(kDt, fuji(), kWgs84);
    }
    const CameraPose valid = controller.pose();
    input.apply(controller);
    EXPECT_TRUE(controller.update(input.dtSeconds, fuji(), kWgs84).inputRejected);
    if (std::isfinite(input.dtSeconds)) twin.update(kDt, fuji(), kWgs84);
    expectSamePose(controller.pose(), twin.pose());
    if (!std::isfinite(input.dtSeconds)) expectSamePose(controller.pose(), valid);
    EXPECT_EQ(controller.velocity(), twin.velocity());
    // The next frame is valid again, and the same as the twin's.
    EXPECT_FALSE(controller.update(kDt, fuji(), kWgs84).inputRejected);
    twin.update(kDt, fuji(), kWgs84);
    expectSamePose(controller.pose(), twin.pose());
    EXPECT_FALSE(samePose(controller.pose(), valid));
  }
  // Driven by a proposal each frame (as `globe play` and `globe view` drive it): a bad proposal
  // keeps the pose of the frame before, and the next good one is taken.
  CameraController driven({at, 0.3, -0.2, 0.0});
  for (int frame = 1; frame <= 5; ++frame) {
    driven.propose({offsetPosition(at, 0.5, 2.0 * frame, at.heightMeters), 0.3, -0.2, 0.0});
    driven.update(kDt, fuji(), kWgs84);
  }
  const CameraPose valid = driven.pose();
  for (const double bad : {kNan, kInf, -kInf}) {
    EXPECT_FALSE(driven.propose({offsetPosition(at, 0.5, 12.0, bad), 0.3, -0.2, 0.0}));
    EXPECT_TRUE(driven.update(kDt, fuji(), kWgs84).inputRejected);
    expectSamePose(driven.pose(), valid);
  }
  ASSERT_TRUE(driven.propose({offsetPosition(at, 0.5, 12.0, at.heightMeters), 0.3, -0.2, 0.0}));
  EXPECT_FALSE(driven.update(kDt, fuji(), kWgs84).inputRejected);
  EXPECT_FALSE(samePose(driven.pose(), valid));
}

// Finite but absurd poses (beyond the path files' ranges): the controller never produces a
// non-finite pose from them, and a valid proposal afterwards is taken.
TEST(CameraController, HugeFiniteProposalsNeverGiveANonFinitePose) {
  const geo::Cartographic at = onSlope(0.5, 2500.0, 300.0);
  const CameraPose huge[] = {
      {{1e300, at.latitudeRadians, 3000.0}, 0, 0, 0},
      {{at.longitudeRadians, at.latitudeRadians, 1e300}, 0, 0, 0},
      {{at.longitudeRadians, at.latitudeRadians, -1e300}, 0, 0, 0},
      {{at.longitudeRadians, std::numbers::pi / 2, 3000.0}, 0, 0, 0},
      {{at.longitudeRadians, -std::numbers::pi / 2, -6.0e6},
       0,
       0,
       0},  // near the centre of the Earth
      {at, 1e300, -1e300, 1e300},
      {{-std::numeric_limits<double>::max(), 0, std::numeric_limits<double>::max()}, 0, 0, 0},
  };
  for (const CameraPose& pose : huge) {
    SCOPED_TRACE(pose.position.heightMeters);
    CameraController controller({at, 0.0, -0.3, 0.0});
    controller.update(kDt, fuji(), kWgs84);
    controller.propose(pose);
    controller.update(kDt, fuji(), kWgs84);
    EXPECT_TRUE(controller.pose().isFinite());
    ASSERT_TRUE(controller.propose({at, 0.1, -0.3, 0.0}, MotionKind::Jump));
    controller.update(kDt, fuji(), kWgs84);
    EXPECT_TRUE(controller.pose().isFinite());
    EXPECT_NEAR(controller.pose().position.heightMeters, at.heightMeters, 1e-6);
  }
}

TEST(CameraController, StateDescribesTheTerrainUnderTheEye) {
  const geo::Cartographic at = onSlope(1.0, 1000.0, 25.0);
  CameraController controller({at, 0.0, 0.0, 0.0});
  const CollisionState state = controller.update(kDt, fuji(), kWgs84);
  EXPECT_FALSE(state.collided);
  EXPECT_EQ(state.response, Response::None);
  EXPECT_TRUE(state.terrainFound);
  EXPECT_EQ(state.tile.level, testing::finestLevel());
  EXPECT_NEAR(state.terrainHeightMeters, drawn(at), 1e-9);
  EXPECT_NEAR(state.clearanceMeters, 25.0, 1e-6);
  EXPECT_EQ(state.motion, MotionKind::None);
  ASSERT_TRUE(controller.setVelocity({0.0, 0.0, 1.0}));
  EXPECT_GT(controller.update(kDt, fuji(), kWgs84).tilesExamined, 0);
  EXPECT_GT(state.nearPlaneClearanceMeters, 20.0);
  EXPECT_EQ(std::string(collision::toString(Response::RaisedForNewTerrain)),
            "raised-for-new-terrain");
  EXPECT_EQ(std::string(toString(MotionKind::Angular)), "angular");
}

}  // namespace
}  // namespace globe::camera
