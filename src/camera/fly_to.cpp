// Picking by ray marching against a height function, and the fly-to pose and animation.
#include "camera/fly_to.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"

namespace globe::camera {
namespace {

constexpr double kPi = std::numbers::pi;

// Height of an ECEF point above the terrain under it; nullopt where undefined.
std::optional<double> clearanceOf(const geo::Ellipsoid& ellipsoid, const glm::dvec3& point,
                                  const TerrainHeightFunction& terrainHeight) {
  const auto c = geo::ecefToCartographic(ellipsoid, point);
  if (!c) return std::nullopt;
  const double ground = terrainHeight(c->longitudeRadians, c->latitudeRadians).value_or(0.0);
  return c->heightMeters - ground;
}

double shortAngle(double radians) { return std::remainder(radians, 2 * kPi); }

}  // namespace

glm::dvec3 pixelRayEcef(const CameraFrame& frame, double xPixels, double yPixels, int widthPixels,
                        int heightPixels, double fovYRadians) {
  const double w = std::max(widthPixels, 1), h = std::max(heightPixels, 1);
  const double ndcX = 2 * xPixels / w - 1, ndcY = 1 - 2 * yPixels / h;
  const double tanHalf = std::tan(fovYRadians / 2);
  return glm::normalize(frame.forward + ndcX * tanHalf * (w / h) * frame.right +
                        ndcY * tanHalf * frame.up);
}

std::optional<glm::dvec3> intersectTerrain(const geo::Ellipsoid& ellipsoid,
                                           const glm::dvec3& originEcefMeters,
                                           const glm::dvec3& direction,
                                           const TerrainHeightFunction& terrainHeight,
                                           double toleranceMeters) {
  constexpr double kStepFraction = 0.3;  // of the clearance: terrain ahead may rise
  constexpr double kMinimumStepMeters = 0.5;
  constexpr int kMaximumSteps = 20000;
  const auto start = clearanceOf(ellipsoid, originEcefMeters, terrainHeight);
  if (!start || *start <= 0) return start ? std::optional(originEcefMeters) : std::nullopt;
  // Past the horizon of the tallest mountain seen from the start the ray can only climb.
  const double r = ellipsoid.semiMajorAxisMeters, h = std::max(*start, 0.0) + 9000.0;
  const double maximumDistance = 2 * std::sqrt(h * (2 * r + h)) + 1e4;
  double before = 0, clearance = *start;
  for (int step = 0; step < kMaximumSteps && before < maximumDistance; ++step) {
    const double t = before + std::max(kStepFraction * clearance, kMinimumStepMeters);
    const auto next = clearanceOf(ellipsoid, originEcefMeters + t * direction, terrainHeight);
    if (!next) return std::nullopt;
    if (*next <= 0) {
      double above = before, below = t;  // bisect the crossing
      while (below - above > toleranceMeters) {
        const double middle = 0.5 * (above + below);
        const auto c = clearanceOf(ellipsoid, originEcefMeters + middle * direction, terrainHeight);
        if (c && *c > 0) {
          above = middle;
        } else {
          below = middle;
        }
      }
      return originEcefMeters + below * direction;
    }
    before = t;
    clearance = *next;
  }
  return std::nullopt;
}

CameraPose flyToEndPose(const geo::Ellipsoid& ellipsoid, const CameraPose& from,
                        const glm::dvec3& targetEcefMeters, const FlyToSettings& settings) {
  const auto target = geo::ecefToCartographic(ellipsoid, targetEcefMeters);
  if (!target) return from;
  const glm::dvec3 eye = geo::cartographicToEcef(ellipsoid, from.position);
  const double distance = std::max(settings.distanceFraction * glm::length(targetEcefMeters - eye),
                                   settings.minimumDistanceMeters);
  // The view direction with the current heading and a downward pitch, in the target's frame.
  const double pitch = std::min(from.pitchRadians, settings.maximumPitchRadians);
  const EastNorthUp enu = eastNorthUp(ellipsoid, *target);
  const double sh = std::sin(from.headingRadians), ch = std::cos(from.headingRadians);
  const glm::dvec3 forward =
      std::cos(pitch) * (sh * enu.east + ch * enu.north) + std::sin(pitch) * enu.up;
  const auto end = geo::ecefToCartographic(ellipsoid, targetEcefMeters - distance * forward);
  if (!end) return from;
  // Heading and pitch again in the end point's own frame, so the target is exactly centred.
  const EastNorthUp there = eastNorthUp(ellipsoid, *end);
  const glm::dvec3 look = glm::normalize(forward);
  CameraPose pose = from;
  pose.position = *end;
  const double east = glm::dot(look, there.east), north = glm::dot(look, there.north);
  // Looking (almost) straight down the heading is undefined: keep the current one.
  if (std::hypot(east, north) > 1e-9) pose.headingRadians = std::atan2(east, north);
  pose.pitchRadians = std::asin(std::clamp(glm::dot(look, there.up), -1.0, 1.0));
  pose.rollRadians = 0;
  return pose;
}

FlyToAnimation::FlyToAnimation(const geo::Ellipsoid& ellipsoid, const CameraPose& from,
                               const CameraPose& to, double durationSeconds)
    : from_(from), to_(to), durationSeconds_(std::max(durationSeconds, 1e-3)) {
  // A long way hops up to see where it goes: half the way's length above the higher end.
  const double way = glm::length(
      geo::cartographicToEcef(ellipsoid, geo::Cartographic{from.position.longitudeRadians,
                                                           from.position.latitudeRadians, 0}) -
      geo::cartographicToEcef(ellipsoid, geo::Cartographic{to.position.longitudeRadians,
                                                           to.position.latitudeRadians, 0}));
  hopMeters_ =
      std::max(0.0, 0.5 * way - std::max(from.position.heightMeters, to.position.heightMeters));
}

CameraPose FlyToAnimation::poseAt(double elapsedSeconds) const {
  const double u = std::clamp(elapsedSeconds / durationSeconds_, 0.0, 1.0);
  if (!(u < 1)) return to_;              // the end, or a non-finite time: the animation is over
  const double s = u * u * (3 - 2 * u);  // smoothstep
  CameraPose pose = to_;
  pose.position.longitudeRadians = geo::wrapLongitudeRadians(
      from_.position.longitudeRadians +
      s * shortAngle(to_.position.longitudeRadians - from_.position.longitudeRadians));
  pose.position.latitudeRadians =
      from_.position.latitudeRadians +
      s * (to_.position.latitudeRadians - from_.position.latitudeRadians);
  const double h0 = from_.position.heightMeters, h1 = to_.position.heightMeters;
  const double height = (h0 > 1 && h1 > 1)
                            ? std::exp(std::log(h0) + s * (std::log(h1) - std::log(h0)))
                            : h0 + s * (h1 - h0);
  pose.position.heightMeters = height + hopMeters_ * std::sin(kPi * s);
  pose.headingRadians =
      from_.headingRadians + s * shortAngle(to_.headingRadians - from_.headingRadians);
  pose.pitchRadians = from_.pitchRadians + s * (to_.pitchRadians - from_.pitchRadians);
  pose.rollRadians = from_.rollRadians + s * shortAngle(to_.rollRadians - from_.rollRadians);
  return pose;
}

}  // namespace globe::camera
