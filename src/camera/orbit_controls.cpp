#include "camera/orbit_controls.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <glm/geometric.hpp>

#include "geo/cartographic.hpp"
#include "geo/ecef.hpp"

namespace globe::camera {

OrbitControls::OrbitControls(const geo::Ellipsoid& ellipsoid, const CameraPose& home,
                             double fovYRadians, const OrbitLimits& limits)
    : ellipsoid_(ellipsoid), home_(home), pose_(home), fovYRadians_(fovYRadians), limits_(limits) {
  if (!pose_.isFinite()) pose_ = CameraPose::fromDegrees(0, 20, 2e7);  // view's default
  clampPose();
  home_ = pose_;
}

void OrbitControls::rotateByDrag(double dxPixels, double dyPixels, int viewportHeightPixels) {
  if (!std::isfinite(dxPixels) || !std::isfinite(dyPixels)) return;
  // Ground metres per pixel at the point looked at: its distance is the clearance over the sine
  // of the depression angle (capped for views near the horizon).
  const double depression = std::max(-pose_.pitchRadians, 0.17);
  const double distanceMeters = std::max(clearanceMeters(), 1.0) / std::sin(depression);
  const double metersPerPixel =
      2 * distanceMeters * std::tan(fovYRadians_ / 2) / std::max(viewportHeightPixels, 1);
  // Screen right and up in east/north for this heading; the camera moves against the drag.
  const double sh = std::sin(pose_.headingRadians), ch = std::cos(pose_.headingRadians);
  const double rightMeters = -dxPixels * metersPerPixel, upMeters = dyPixels * metersPerPixel;
  const double eastMeters = rightMeters * ch + upMeters * sh;
  const double northMeters = -rightMeters * sh + upMeters * ch;
  if (!std::isfinite(eastMeters) || !std::isfinite(northMeters)) return;  // a drag that overflows
  const double radiusMeters = ellipsoid_.semiMajorAxisMeters;
  const double cosLatitude = std::max(std::cos(pose_.position.latitudeRadians), 0.02);
  pose_.position.latitudeRadians += northMeters / radiusMeters;
  pose_.position.longitudeRadians += eastMeters / (radiusMeters * cosLatitude);
  clampPose();
}

void OrbitControls::tiltByDrag(double dxPixels, double dyPixels) {
  if (!std::isfinite(dxPixels) || !std::isfinite(dyPixels)) return;
  pose_.headingRadians += dxPixels * kTiltRadiansPerPixel;
  pose_.pitchRadians -= dyPixels * kTiltRadiansPerPixel;
  clampPose();
}

void OrbitControls::zoom(double notches) {
  if (!std::isfinite(notches)) return;
  const double clearance = std::max(clearanceMeters(), limits_.minimumClearanceMeters);
  pose_.position.heightMeters =
      groundHeightMeters_ + clearance * std::pow(kZoomFactorPerNotch, notches);
  clampPose();
}

bool OrbitControls::lookFrom(const glm::dvec3& positionEcefMeters, const glm::dvec3& forward,
                             const glm::dvec3& up) {
  const auto position = geo::ecefToCartographic(ellipsoid_, positionEcefMeters);
  if (!position || !std::isfinite(forward.x + forward.y + forward.z)) return false;
  const EastNorthUp enu = eastNorthUp(ellipsoid_, *position);
  CameraPose next = pose_;
  next.position = *position;
  next.pitchRadians = std::asin(std::clamp(glm::dot(forward, enu.up), -1.0, 1.0));
  // The heading's direction: cos(pitch)·forward − sin(pitch)·up is horizontal for a level camera
  // and well defined looking straight down (where forward alone has no horizontal part).
  const glm::dvec3 level = std::cos(next.pitchRadians) * forward - std::sin(next.pitchRadians) * up;
  const double east = glm::dot(level, enu.east), north = glm::dot(level, enu.north);
  // Straight down or up the heading is free: keep it.
  if (std::hypot(east, north) > 1e-9) next.headingRadians = std::atan2(east, north);
  next.rollRadians = 0;
  if (!next.isFinite()) return false;
  pose_ = next;
  return true;
}

void OrbitControls::zoomToward(double notches, const glm::dvec3& targetEcefMeters) {
  if (!std::isfinite(notches) ||
      !std::isfinite(targetEcefMeters.x + targetEcefMeters.y + targetEcefMeters.z)) {
    return;
  }
  const CameraFrame frame = cameraFrame(ellipsoid_, pose_);
  const glm::dvec3 toTarget = targetEcefMeters - frame.positionEcefMeters;
  const double distance = glm::length(toTarget);
  if (!(distance > 0)) return;
  // Never nearer than the minimum clearance, never farther than the height limit allows.
  const double wanted = distance * std::pow(kZoomFactorPerNotch, notches);
  const double kept =
      std::clamp(wanted, limits_.minimumClearanceMeters, limits_.maximumHeightMeters);
  // Where the target is seen (camera right and up components of its direction): kept there.
  const glm::dvec2 seen(glm::dot(toTarget, frame.right) / distance,
                        glm::dot(toTarget, frame.up) / distance);
  seeFromDistance(targetEcefMeters, seen, kept, toTarget / distance);
  clampPose();
}

void OrbitControls::seeFromDistance(const glm::dvec3& targetEcefMeters, glm::dvec2 seen,
                                    double distanceMeters, const glm::dvec3& direction) {
  // The camera at `distanceMeters` from the target in the direction u(a, b) = direction tilted
  // by a and b toward two perpendiculars; its heading and pitch (in its own east-north-up frame)
  // as they are, so a and b are solved for (Newton) until the target is seen at `seen`.
  const glm::dvec3 side = std::abs(direction.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(direction, side));
  const glm::dvec3 e2 = glm::cross(direction, e1);
  const auto placed = [&](double a, double b) {
    const glm::dvec3 u = glm::normalize(direction + a * e1 + b * e2);
    return geo::ecefToCartographic(ellipsoid_, targetEcefMeters - distanceMeters * u);
  };
  const auto residual = [&](double a, double b) {
    CameraPose trial = pose_;
    const auto position = placed(a, b);
    if (!position) return glm::dvec2(std::nan(""));
    trial.position = *position;
    const CameraFrame f = cameraFrame(ellipsoid_, trial);
    const glm::dvec3 toTarget = glm::normalize(targetEcefMeters - f.positionEcefMeters);
    return glm::dvec2(glm::dot(toTarget, f.right) - seen.x, glm::dot(toTarget, f.up) - seen.y);
  };
  const auto size = [](glm::dvec2 r) { return std::abs(r.x) + std::abs(r.y); };
  double a = 0, b = 0;
  for (int iteration = 0; iteration < 10; ++iteration) {
    const glm::dvec2 r = residual(a, b);
    if (!(size(r) > 1e-13)) break;
    constexpr double kStep = 1e-8;
    const glm::dvec2 dA = (residual(a + kStep, b) - r) / kStep;
    const glm::dvec2 dB = (residual(a, b + kStep) - r) / kStep;
    const double det = dA.x * dB.y - dB.x * dA.y;
    if (!(std::abs(det) > 1e-12)) break;
    a -= (r.x * dB.y - dB.x * r.y) / det;
    b -= (dA.x * r.y - r.x * dA.y) / det;
  }
  // Not solved (no such place, or it does not converge): along the line, the look kept.
  if (!(size(residual(a, b)) < size(residual(0, 0)))) a = b = 0;
  if (const auto position = placed(a, b)) {
    pose_.position = *position;
    pose_.rollRadians = 0;
  }
}

bool OrbitControls::dragGrabbed(const glm::dvec3& grabbedEcefMeters, const glm::dvec3& rayEcef) {
  const double radius = glm::length(grabbedEcefMeters);
  if (!std::isfinite(radius) || !(radius > 0) || !std::isfinite(rayEcef.x + rayEcef.y + rayEcef.z))
    return false;
  const CameraFrame frame = cameraFrame(ellipsoid_, pose_);
  // Where the ray meets the sphere through the grabbed point (the near side).
  const glm::dvec3& origin = frame.positionEcefMeters;
  const double half = glm::dot(origin, rayEcef);
  const double excess = glm::dot(origin, origin) - radius * radius;
  const double discriminant = half * half - excess;
  if (!(discriminant >= 0)) return false;
  const double along = -half - std::sqrt(discriminant);
  if (!(along > 0)) return false;
  const glm::dvec3 hit = glm::normalize(origin + along * rayEcef);
  const glm::dvec3 grabbed = grabbedEcefMeters / radius;
  // CesiumJS's rotate3D about a constrained axis: the globe turns about the polar axis and about
  // the camera's own east axis (through the centre). Both carry the camera's east-north-up frame
  // onto the new one, so the heading stays (north up stays up); a rotation about any other axis
  // (the shortest from hit to grabbed) would turn it. First the latitude: the turn b about the
  // east axis that brings the hit to the grabbed point's z.
  const double longitude = pose_.position.longitudeRadians;
  const glm::dvec3 meridian(std::cos(longitude), std::sin(longitude), 0);
  const glm::dvec3 east(-std::sin(longitude), std::cos(longitude), 0);
  const double u = glm::dot(hit, meridian), w = hit.z, reach = std::hypot(u, w);
  if (!(reach > 1e-6)) return false;  // on the east axis: no turn about it moves the hit
  // A turn by b about east takes (u, w) to z = reach·sin(phase − b); of the two solutions the
  // smaller turn, and never the camera past the orbit's latitude limit (then the grab lags).
  const double phase = std::atan2(w, u);
  const double reached = std::asin(std::clamp(grabbed.z / reach, -1.0, 1.0));
  double b = std::remainder(phase - reached, 2 * std::numbers::pi);
  const double other = std::remainder(phase - std::numbers::pi + reached, 2 * std::numbers::pi);
  if (std::abs(other) < std::abs(b)) b = other;
  const double cameraLatitude = std::atan2(origin.z, std::hypot(origin.x, origin.y));
  b = std::clamp(b, cameraLatitude - limits_.maximumLatitudeRadians,
                 cameraLatitude + limits_.maximumLatitudeRadians);
  const auto turn = [](const glm::dvec3& v, const glm::dvec3& k, double angle) {
    // Rodrigues: v turned by angle about the unit axis k.
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1 - c);
  };
  // Then the longitude: the turn about the polar axis that brings it to the grabbed point's.
  const glm::dvec3 turnedHit = turn(hit, east, b);
  const double a = std::atan2(grabbed.y, grabbed.x) - std::atan2(turnedHit.y, turnedHit.x);
  const glm::dvec3 pole(0, 0, 1);
  const auto rotate = [&](const glm::dvec3& v) { return turn(turn(v, east, b), pole, a); };
  if (!std::isfinite(a + b)) return false;
  if (lookFrom(rotate(origin), rotate(frame.forward), rotate(frame.up))) clampPose();
  return true;
}

void OrbitControls::northUp(const std::optional<glm::dvec3>& pivotEcefMeters) {
  const auto pivot =
      pivotEcefMeters ? geo::ecefToCartographic(ellipsoid_, *pivotEcefMeters) : std::nullopt;
  if (!pivot) {
    pose_.headingRadians = 0;
    return;
  }
  // The heading as seen from the pivot, turned to 0 about it.
  const CameraFrame frame = cameraFrame(ellipsoid_, pose_);
  const EastNorthUp enu = eastNorthUp(ellipsoid_, *pivot);
  const glm::dvec3 look = *pivotEcefMeters - frame.positionEcefMeters;
  const double east = glm::dot(look, enu.east), north = glm::dot(look, enu.north);
  const double heading = std::hypot(east, north) > 1e-9 * glm::length(look)
                             ? std::atan2(east, north)
                             : pose_.headingRadians;
  tiltAbout(-std::remainder(heading, 2 * std::numbers::pi) / kTiltRadiansPerPixel, 0,
            *pivotEcefMeters);
}

void OrbitControls::tiltAbout(double dxPixels, double dyPixels, const glm::dvec3& pivotEcefMeters) {
  if (!std::isfinite(dxPixels) || !std::isfinite(dyPixels) ||
      !std::isfinite(pivotEcefMeters.x + pivotEcefMeters.y + pivotEcefMeters.z)) {
    return;
  }
  const auto pivot = geo::ecefToCartographic(ellipsoid_, pivotEcefMeters);
  if (!pivot) return;
  const CameraFrame frame = cameraFrame(ellipsoid_, pose_);
  const glm::dvec3 fromPivot = frame.positionEcefMeters - pivotEcefMeters;
  const double distance = glm::length(fromPivot);
  if (!(distance > 0)) return;
  // The view direction as seen in the pivot's east-north-up frame, turned and tilted there.
  const EastNorthUp enu = eastNorthUp(ellipsoid_, *pivot);
  const glm::dvec3 look = -fromPivot / distance;
  const double east = glm::dot(look, enu.east), north = glm::dot(look, enu.north);
  double heading = std::hypot(east, north) > 1e-9 ? std::atan2(east, north) : pose_.headingRadians;
  double pitch = std::asin(std::clamp(glm::dot(look, enu.up), -1.0, 1.0));
  heading += dxPixels * kTiltRadiansPerPixel;
  pitch = std::clamp(pitch - dyPixels * kTiltRadiansPerPixel, limits_.minimumPitchRadians,
                     limits_.maximumPitchRadians - 0.01);  // level would lose the pivot
  const glm::dvec3 forward = std::cos(pitch) * std::sin(heading) * enu.east +
                             std::cos(pitch) * std::cos(heading) * enu.north +
                             std::sin(pitch) * enu.up;
  const glm::dvec3 up =
      -std::sin(pitch) * (std::sin(heading) * enu.east + std::cos(heading) * enu.north) +
      std::cos(pitch) * enu.up;
  if (lookFrom(pivotEcefMeters - distance * forward, forward, up)) clampPose();
}

bool OrbitControls::setGroundHeight(double groundHeightMeters) {
  if (!std::isfinite(groundHeightMeters)) return false;
  groundHeightMeters_ = groundHeightMeters;
  const CameraPose before = pose_;
  clampPose();
  return pose_.position.heightMeters != before.position.heightMeters;
}

void OrbitControls::clampPose() {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  pose_.position.latitudeRadians =
      std::clamp(pose_.position.latitudeRadians, -limits_.maximumLatitudeRadians,
                 limits_.maximumLatitudeRadians);
  pose_.position.longitudeRadians = geo::wrapLongitudeRadians(pose_.position.longitudeRadians);
  pose_.headingRadians = std::remainder(pose_.headingRadians, kTwoPi);
  pose_.pitchRadians =
      std::clamp(pose_.pitchRadians, limits_.minimumPitchRadians, limits_.maximumPitchRadians);
  pose_.position.heightMeters = std::clamp(
      pose_.position.heightMeters, groundHeightMeters_ + limits_.minimumClearanceMeters,
      std::max(limits_.maximumHeightMeters, groundHeightMeters_ + limits_.minimumClearanceMeters));
}

std::vector<std::string> describeStartClamp(const CameraPose& asked, const CameraPose& started) {
  std::vector<std::string> said;
  const auto degrees = [](double radians) {
    char text[32];
    std::snprintf(text, sizeof text, "%g°", std::round(geo::radiansToDegrees(radians) * 1e3) / 1e3);
    return std::string(text);
  };
  if (asked.pitchRadians != started.pitchRadians) {
    said.push_back("pitch " + degrees(asked.pitchRadians) + " is beyond what orbit mode looks at " +
                   "(straight down to level): starting at " + degrees(started.pitchRadians) +
                   (asked.pitchRadians > started.pitchRadians ? "; fly mode (F) looks up" : ""));
  }
  if (asked.position.latitudeRadians != started.position.latitudeRadians) {
    said.push_back("latitude " + degrees(asked.position.latitudeRadians) +
                   " is closer to the pole than orbit mode goes: starting at " +
                   degrees(started.position.latitudeRadians));
  }
  if (asked.position.heightMeters != started.position.heightMeters) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "height %.0f m is outside orbit mode's range: starting at %.0f m",
                  asked.position.heightMeters, started.position.heightMeters);
    said.emplace_back(text);
  }
  return said;
}

}  // namespace globe::camera
