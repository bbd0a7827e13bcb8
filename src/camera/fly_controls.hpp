// Fly-mode camera controls for `globe view`: WASD/QE move along the view (ENU frame), speed scales
// with the height above the terrain, the mouse turns heading and pitch. Pure math, no GLFW.
#pragma once

#include <glm/vec3.hpp>

#include "camera/camera_pose.hpp"
#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::camera {

// The movement keys held now.
struct FlyKeys {
  bool forward = false, back = false, left = false, right = false;
  bool down = false, up = false;
  bool fast = false;  // Shift
  bool moving() const;
};

struct FlySettings {
  double minimumSpeedMetersPerSecond = 2.0;
  double speedPerClearancePerSecond = 1.0;  // speed = clearance * this, at least the minimum
  double fastFactor = 5.0;                  // Shift
  double lookRadiansPerPixel = 0.003;
  double maximumPitchRadians = geo::degreesToRadians(89);  // either way from the horizon
};

// Speed for this clearance above the terrain (negative clearances count as 0), times `factor`
// (the user's scroll-wheel speed factor) and the fast factor with Shift.
double flySpeedMetersPerSecond(double clearanceMeters, bool fast, double factor = 1.0,
                               const FlySettings& settings = {});

// The unit direction (east, north, up) the held keys move in: W/S along the view direction
// (heading and pitch), A/D along the horizontal right, E/Q along the local up; zero when the keys
// cancel or none is held.
glm::dvec3 flyDirectionEnu(const FlyKeys& keys, double headingRadians, double pitchRadians);

// The ECEF velocity (m/s) for the pose and keys at this clearance.
glm::dvec3 flyVelocityEcef(const geo::Ellipsoid& ellipsoid, const CameraPose& pose,
                           const FlyKeys& keys, double clearanceMeters, double factor = 1.0,
                           const FlySettings& settings = {});

// The pose `dtSeconds` of flight later: the position moved in a straight line (ECEF) by the
// velocity, heading and pitch kept. The pose itself when nothing moves or the move is undefined
// (a non-finite velocity or dt).
CameraPose flyStep(const geo::Ellipsoid& ellipsoid, const CameraPose& pose,
                   const glm::dvec3& velocityEcefMetersPerSecond, double dtSeconds);

// Mouse look: a drag (or a captured-cursor motion) of dx, dy pixels turns the heading right for
// dx > 0 and tilts the view up for dy < 0 (window y points down); the pitch is clamped and the
// heading wrapped into [0, 2 pi). Non-finite deltas are ignored: the pose is returned as it is.
CameraPose lookByPixels(const CameraPose& pose, double dxPixels, double dyPixels,
                        const FlySettings& settings = {});
// The same by angles (arrow keys).
CameraPose lookByRadians(const CameraPose& pose, double headingRadians, double pitchRadians,
                         const FlySettings& settings = {});

// The clearance fly speed follows (the speed is proportional to it): it moves toward the measured
// clearance by at most x2 per second up and /8 per second down, so passing a cliff edge (32 m ->
// 1,845 m in a few frames) accelerates smoothly instead of lurching into the far rim, and a
// rising ground still slows the flight within a fraction of a second.
class SmoothedClearance {
 public:
  static constexpr double kRisePerSecond = 2.0, kFallPerSecond = 8.0;
  static constexpr double kFloorMeters = 1.0;  // ratios need a positive value
  // The smoothed clearance after `dtSeconds` more of flight at `clearanceMeters` (NaN or a
  // negative clearance counts as the floor); the first call takes the clearance as it is.
  double update(double clearanceMeters, double dtSeconds);
  void reset() { valueMeters_ = 0; }
  bool started() const { return valueMeters_ > 0; }
  double value() const { return valueMeters_; }

 private:
  double valueMeters_ = 0;  // 0: not started
};

// Fly mode's speed factor (scroll wheel, +/-): whole powers of two from 1/8 to 64, so steps up
// and back down always return exactly to 1. Fractional wheel notches (touchpads) add up until
// they make a whole step.
class SpeedSteps {
 public:
  static constexpr int kSlowest = -3, kFastest = 6;  // x1/8 .. x64
  void change(double notches);
  double factor() const;
  int step() const { return step_; }

 private:
  int step_ = 0;
  double pendingNotches_ = 0;
};

}  // namespace globe::camera
