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
  const glm::dvec3 position = targetEcefMeters - toTarget * (kept / distance);
  // Where the target is seen (camera coordinates): kept there with the horizon level (roll 0),
  // so the ground under the cursor stays under it; heading and pitch are solved for (Newton).
  const glm::dvec3 seen(glm::dot(toTarget, frame.right) / distance,
                        glm::dot(toTarget, frame.up) / distance, 0.0);
  if (!lookFrom(position, frame.forward, frame.up)) return;
  const glm::dvec3 direction = toTarget / distance;
  const auto residual = [&](double heading, double pitch) {
    CameraPose trial = pose_;
    trial.headingRadians = heading;
    trial.pitchRadians = pitch;
    const CameraFrame f = cameraFrame(ellipsoid_, trial);
    return glm::dvec2(glm::dot(direction, f.right) - seen.x, glm::dot(direction, f.up) - seen.y);
  };
  // Orbit's pitch range: a solution past straight down (zooming out of a nadir view near an
  // edge) is not reachable without a roll; then the nearest pose within the range is kept.
  const auto inRange = [&](double pitch) {
    return std::clamp(pitch, limits_.minimumPitchRadians, limits_.maximumPitchRadians);
  };
  const double startHeading = pose_.headingRadians, startPitch = inRange(pose_.pitchRadians);
  double heading = startHeading, pitch = startPitch;
  for (int iteration = 0; iteration < 6; ++iteration) {
    const glm::dvec2 r = residual(heading, pitch);
    if (std::abs(r.x) + std::abs(r.y) < 1e-12) break;
    constexpr double kStep = 1e-7;
    const glm::dvec2 dh = (residual(heading + kStep, pitch) - r) / kStep;
    const glm::dvec2 dp = (residual(heading, pitch + kStep) - r) / kStep;
    const double det = dh.x * dp.y - dp.x * dh.y;
    if (!(std::abs(det) > 1e-12)) break;
    heading -= (r.x * dp.y - dp.x * r.y) / det;
    pitch = inRange(pitch - (dh.x * r.y - r.x * dh.y) / det);
  }
  const auto error = [&](double h, double p) {
    const glm::dvec2 r = residual(h, p);
    return std::abs(r.x) + std::abs(r.y);
  };
  if (std::isfinite(heading) && std::isfinite(pitch) &&
      error(heading, pitch) < error(startHeading, startPitch)) {
    pose_.headingRadians = heading;
    pose_.pitchRadians = pitch;
  }
  // At the end of the pitch range (zooming out of a straight-down view off the centre) the look
  // cannot turn far enough: the camera moves sideways instead, at the same height, until the
  // target is seen where it was.
  if (error(pose_.headingRadians, pose_.pitchRadians) > 1e-10)
    seeFromNearby(targetEcefMeters, glm::dvec2(seen));
  clampPose();
}

void OrbitControls::seeFromNearby(const glm::dvec3& targetEcefMeters, glm::dvec2 seen) {
  const auto residual = [&](double lon, double lat) {
    CameraPose trial = pose_;
    trial.position.longitudeRadians = lon;
    trial.position.latitudeRadians = lat;
    const CameraFrame f = cameraFrame(ellipsoid_, trial);
    const glm::dvec3 direction = glm::normalize(targetEcefMeters - f.positionEcefMeters);
    return glm::dvec2(glm::dot(direction, f.right) - seen.x, glm::dot(direction, f.up) - seen.y);
  };
  double lon = pose_.position.longitudeRadians, lat = pose_.position.latitudeRadians;
  const glm::dvec2 start = residual(lon, lat);
  for (int iteration = 0; iteration < 8; ++iteration) {
    const glm::dvec2 r = residual(lon, lat);
    if (std::abs(r.x) + std::abs(r.y) < 1e-13) break;
    constexpr double kStep = 1e-9;  // radians: ~6 mm on the ground
    const glm::dvec2 dLon = (residual(lon + kStep, lat) - r) / kStep;
    const glm::dvec2 dLat = (residual(lon, lat + kStep) - r) / kStep;
    const double det = dLon.x * dLat.y - dLat.x * dLon.y;
    if (!(std::abs(det) > 1e-12)) break;
    lon -= (r.x * dLat.y - dLat.x * r.y) / det;
    lat -= (dLon.x * r.y - r.x * dLon.y) / det;
  }
  const glm::dvec2 end = residual(lon, lat);
  if (std::isfinite(lon) && std::isfinite(lat) &&
      std::abs(end.x) + std::abs(end.y) < std::abs(start.x) + std::abs(start.y)) {
    pose_.position.longitudeRadians = lon;
    pose_.position.latitudeRadians = lat;
  }
}

bool OrbitControls::dragGrabbed(const glm::dvec3& grabbedEcefMeters, const glm::dvec3& rayEcef) {
  const double radius = glm::length(grabbedEcefMeters);
  if (!std::isfinite(radius) || !(radius > 0) || !std::isfinite(rayEcef.x + rayEcef.y + rayEcef.z))
    return false;
  const CameraFrame frame = cameraFrame(ellipsoid_, pose_);
  // Where the ray meets the sphere through the grabbed point (the near side).
  const glm::dvec3& origin = frame.positionEcefMeters;
  const double b = glm::dot(origin, rayEcef);
  const double c = glm::dot(origin, origin) - radius * radius;
  const double discriminant = b * b - c;
  if (!(discriminant >= 0)) return false;
  const double along = -b - std::sqrt(discriminant);
  if (!(along > 0)) return false;
  const glm::dvec3 hit = glm::normalize(origin + along * rayEcef);
  const glm::dvec3 grabbed = grabbedEcefMeters / radius;
  const glm::dvec3 axis = glm::cross(hit, grabbed);
  const double sine = glm::length(axis), cosine = glm::dot(hit, grabbed);
  if (!(sine > 1e-15)) return true;  // already there
  // Rodrigues: the rotation by atan2(sine, cosine) about the unit axis.
  const glm::dvec3 k = axis / sine;
  const auto rotate = [&](const glm::dvec3& v) {
    return v * cosine + glm::cross(k, v) * sine + k * glm::dot(k, v) * (1 - cosine);
  };
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
