// Fly-mode maths: directions in the local east-north-up frame, speed from the clearance, look.
#include "camera/fly_controls.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"

namespace globe::camera {

bool FlyKeys::moving() const { return forward != back || left != right || down != up; }

double flySpeedMetersPerSecond(double clearanceMeters, bool fast, double factor,
                               const FlySettings& settings) {
  const double clearance = std::isfinite(clearanceMeters) ? std::max(clearanceMeters, 0.0) : 0.0;
  const double speed = std::max(settings.minimumSpeedMetersPerSecond,
                                settings.speedPerClearancePerSecond * clearance);
  return speed * factor * (fast ? settings.fastFactor : 1.0);
}

glm::dvec3 flyDirectionEnu(const FlyKeys& keys, double headingRadians, double pitchRadians) {
  const double sh = std::sin(headingRadians), ch = std::cos(headingRadians);
  const double sp = std::sin(pitchRadians), cp = std::cos(pitchRadians);
  const glm::dvec3 forward(cp * sh, cp * ch, sp);  // the view direction
  const glm::dvec3 right(ch, -sh, 0.0);            // horizontal, 90 deg clockwise of the heading
  const glm::dvec3 up(0.0, 0.0, 1.0);
  glm::dvec3 direction(0.0);
  if (keys.forward) direction += forward;
  if (keys.back) direction -= forward;
  if (keys.right) direction += right;
  if (keys.left) direction -= right;
  if (keys.up) direction += up;
  if (keys.down) direction -= up;
  const double length = glm::length(direction);
  return length > 1e-12 ? direction / length : glm::dvec3(0.0);
}

glm::dvec3 flyVelocityEcef(const geo::Ellipsoid& ellipsoid, const CameraPose& pose,
                           const FlyKeys& keys, double clearanceMeters, double factor,
                           const FlySettings& settings) {
  const glm::dvec3 d = flyDirectionEnu(keys, pose.headingRadians, pose.pitchRadians);
  const EastNorthUp enu = eastNorthUp(ellipsoid, pose.position);
  const double speed = flySpeedMetersPerSecond(clearanceMeters, keys.fast, factor, settings);
  return speed * (d.x * enu.east + d.y * enu.north + d.z * enu.up);
}

CameraPose flyStep(const geo::Ellipsoid& ellipsoid, const CameraPose& pose,
                   const glm::dvec3& velocityEcefMetersPerSecond, double dtSeconds) {
  const glm::dvec3 displacement = velocityEcefMetersPerSecond * dtSeconds;
  const double length = glm::length(displacement);
  if (!(length > 0.0 && std::isfinite(length))) return pose;  // NaN, inf or no motion
  const auto moved = geo::ecefToCartographic(
      ellipsoid, geo::cartographicToEcef(ellipsoid, pose.position) + displacement);
  if (!moved) return pose;
  CameraPose next = pose;
  next.position = *moved;
  return next;
}

CameraPose lookByPixels(const CameraPose& pose, double dxPixels, double dyPixels,
                        const FlySettings& settings) {
  return lookByRadians(pose, dxPixels * settings.lookRadiansPerPixel,
                       -dyPixels * settings.lookRadiansPerPixel, settings);
}

CameraPose lookByRadians(const CameraPose& pose, double headingRadians, double pitchRadians,
                         const FlySettings& settings) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  if (!std::isfinite(headingRadians) || !std::isfinite(pitchRadians)) return pose;
  CameraPose next = pose;
  next.headingRadians = std::fmod(pose.headingRadians + headingRadians, kTwoPi);
  if (next.headingRadians < 0) next.headingRadians += kTwoPi;
  next.pitchRadians = std::clamp(pose.pitchRadians + pitchRadians, -settings.maximumPitchRadians,
                                 settings.maximumPitchRadians);
  return next;
}

double SmoothedClearance::update(double clearanceMeters, double dtSeconds) {
  const double target =
      std::isfinite(clearanceMeters) ? std::max(clearanceMeters, kFloorMeters) : kFloorMeters;
  if (valueMeters_ <= 0 || !std::isfinite(dtSeconds)) {
    valueMeters_ = target;
    return valueMeters_;
  }
  const double dt = std::clamp(dtSeconds, 0.0, 1.0);
  valueMeters_ = std::clamp(target, valueMeters_ / std::pow(kFallPerSecond, dt),
                            valueMeters_ * std::pow(kRisePerSecond, dt));
  return valueMeters_;
}

void SpeedSteps::change(double notches) {
  if (!std::isfinite(notches)) return;
  pendingNotches_ += notches;
  const double whole = std::trunc(pendingNotches_);
  pendingNotches_ -= whole;
  const double next = std::clamp(step_ + whole, double{kSlowest}, double{kFastest});
  step_ = static_cast<int>(next);
  if (step_ == kSlowest || step_ == kFastest) pendingNotches_ = 0;  // no credit past a limit
}

double SpeedSteps::factor() const { return std::ldexp(1.0, step_); }

}  // namespace globe::camera
