// Orbit and fly-to shots as keyframes (path_generators.hpp).
#include "camera/path_generators.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "camera/fly_to.hpp"
#include "geo/ecef.hpp"

namespace globe::camera {
namespace {

PathKeyframe keyframeOf(double timeSeconds, const CameraPose& pose) {
  PathKeyframe key;
  key.timeSeconds = timeSeconds;
  key.longitudeDegrees = pose.position.longitudeDegrees();
  key.latitudeDegrees = pose.position.latitudeDegrees();
  key.heightMeters = pose.position.heightMeters;
  key.headingDegrees = geo::radiansToDegrees(pose.headingRadians);
  key.pitchDegrees = geo::radiansToDegrees(pose.pitchRadians);
  key.rollDegrees = geo::radiansToDegrees(pose.rollRadians);
  return key;
}

}  // namespace

std::vector<PathKeyframe> orbitKeyframes(const OrbitShot& shot) {
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  const geo::Cartographic centre = geo::Cartographic::fromDegrees(
      shot.centre.longitudeDegrees, shot.centre.latitudeDegrees, shot.centre.heightMeters);
  const EastNorthUp enu = eastNorthUp(wgs84, centre);
  const glm::dvec3 centreEcef = geo::cartographicToEcef(wgs84, centre);
  const int steps = std::max(2, static_cast<int>(std::ceil(std::abs(shot.degrees) / 10.0)));
  std::vector<PathKeyframe> keys;
  for (int j = 0; j <= steps; ++j) {
    const double share = static_cast<double>(j) / steps;
    const double bearing =
        geo::degreesToRadians(shot.startBearingDegrees + shot.degrees * share);
    const glm::dvec3 out = std::sin(bearing) * enu.east + std::cos(bearing) * enu.north;
    const auto at = geo::ecefToCartographic(wgs84, centreEcef + shot.radiusMeters * out);
    CameraPose pose;
    pose.position = at.value_or(centre);
    pose.position.heightMeters = shot.centre.heightMeters + shot.altitudeMeters;
    PathKeyframe key = keyframeOf(shot.durationSeconds * share, pose);
    key.heightAboveTerrain = shot.centre.heightAboveTerrain;
    key.target = shot.centre;
    keys.push_back(key);
  }
  return keys;
}

std::vector<PathKeyframe> flyToKeyframes(const FlyToShot& shot) {
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  const FlyToAnimation flight(wgs84, shot.from, shot.to, shot.durationSeconds);
  const int steps =
      std::clamp(static_cast<int>(std::ceil(shot.durationSeconds * 4.0)), 15, 3999);
  std::vector<PathKeyframe> keys;
  for (int j = 0; j <= steps; ++j) {
    const double t = shot.durationSeconds * j / steps;
    keys.push_back(keyframeOf(t, j == steps ? shot.to : flight.poseAt(t)));
  }
  return keys;
}

std::vector<PathKeyframe> withBounceArcs(const std::vector<PathKeyframe>& keys,
                                         const std::vector<bool>& bounceInto) {
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  std::vector<PathKeyframe> out;
  for (size_t k = 0; k < keys.size(); ++k) {
    if (k == 0 || k >= bounceInto.size() || !bounceInto[k]) {
      out.push_back(keys[k]);
      continue;
    }
    const PathKeyframe& a = keys[k - 1];
    const PathKeyframe& b = keys[k];
    const auto poseOf = [](const PathKeyframe& key) {
      return CameraPose::fromDegrees(key.longitudeDegrees, key.latitudeDegrees, key.heightMeters,
                                     key.headingDegrees, key.pitchDegrees, key.rollDegrees);
    };
    const double span = b.timeSeconds - a.timeSeconds;
    const CameraPose apex = FlyToAnimation(wgs84, poseOf(a), poseOf(b), span).poseAt(0.5 * span);
    const bool hops = apex.position.heightMeters > std::max(a.heightMeters, b.heightMeters) + 1.0;
    if (hops && a.heightAboveTerrain == b.heightAboveTerrain) {
      out.back().ease = kEaseIn;
      PathKeyframe middle = keyframeOf(a.timeSeconds + 0.5 * span, apex);
      middle.heightAboveTerrain = a.heightAboveTerrain;
      middle.ease = kEaseOut;
      out.push_back(middle);
    } else {
      out.back().ease = kEaseInOut;
    }
    out.push_back(b);
  }
  return out;
}

}  // namespace globe::camera
