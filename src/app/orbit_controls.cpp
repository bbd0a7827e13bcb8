#include "app/orbit_controls.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "geo/cartographic.hpp"

namespace globe::app {

OrbitControls::OrbitControls(const geo::Ellipsoid& ellipsoid, const camera::CameraPose& home,
                             double fovYRadians, const OrbitLimits& limits)
    : ellipsoid_(ellipsoid), home_(home), pose_(home), fovYRadians_(fovYRadians), limits_(limits) {
  if (!pose_.isFinite()) pose_ = camera::CameraPose::fromDegrees(0, 20, 2e7);  // view's default
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

bool OrbitControls::setGroundHeight(double groundHeightMeters) {
  if (!std::isfinite(groundHeightMeters)) return false;
  groundHeightMeters_ = groundHeightMeters;
  const camera::CameraPose before = pose_;
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

std::vector<std::string> describeStartClamp(const camera::CameraPose& asked,
                                            const camera::CameraPose& started) {
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

}  // namespace globe::app
