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

}  // namespace globe::camera
