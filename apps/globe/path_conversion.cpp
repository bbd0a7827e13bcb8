// io::CameraPathFile → camera::CameraPath: degrees to radians, terrain-relative heights resolved.
#include "apps/globe/path_conversion.hpp"

#include <optional>

#include "camera/look_at.hpp"
#include "geo/ecef.hpp"

namespace globe::app {

namespace {

// Where a target is, in ECEF: its height above the terrain resolved there.
Result<glm::dvec3> targetEcef(const camera::PathTarget& target,
                              const TerrainHeightFunction& terrainHeight,
                              const geo::Ellipsoid& ellipsoid) {
  geo::Cartographic point = geo::Cartographic::fromDegrees(
      target.longitudeDegrees, target.latitudeDegrees, target.heightMeters);
  if (target.heightAboveTerrain) {
    auto ground = terrainHeight(point.longitudeRadians, point.latitudeRadians);
    if (!ground) return Error{ground.error()};
    point.heightMeters += *ground;
  }
  return geo::cartographicToEcef(ellipsoid, point);
}

}  // namespace

Result<camera::CameraPath> toCameraPath(const camera::CameraPathFile& file,
                                        const TerrainHeightFunction& terrainHeight,
                                        const geo::Ellipsoid& ellipsoid) {
  const auto interpolation = camera::parsePathInterpolation(file.interpolation);
  if (!interpolation) {
    return makeError("interpolation '" + file.interpolation + "' is not linear or smooth");
  }
  camera::CameraPath path;
  path.interpolation = *interpolation;
  path.logarithmicAltitude = file.logarithmicAltitude;
  for (size_t k = 0; k < file.keyframes.size(); ++k) {
    const camera::PathKeyframe& key = file.keyframes[k];
    camera::CameraPose pose =
        camera::CameraPose::fromDegrees(key.longitudeDegrees, key.latitudeDegrees, key.heightMeters,
                                        key.headingDegrees, key.pitchDegrees, key.rollDegrees);
    double groundMeters = 0;
    if (key.heightAboveTerrain) {
      // Kept above the terrain (camera::samplePath adds it where the path is); read here once
      // so that a terrain that cannot be read is an error naming the keyframe.
      auto ground = terrainHeight(pose.position.longitudeRadians, pose.position.latitudeRadians);
      if (!ground) {
        return makeError("keyframes[" + std::to_string(k) +
                         "]: the terrain height: " + ground.error());
      }
      groundMeters = *ground;
    }
    std::optional<glm::dvec3> target;
    if (key.target) {
      auto resolved = targetEcef(*key.target, terrainHeight, ellipsoid);
      if (!resolved) {
        return makeError("keyframes[" + std::to_string(k) +
                         "].target: the terrain height: " + resolved.error());
      }
      target = *resolved;
      // Turned from where it really is (on the terrain, for an aboveTerrain keyframe).
      camera::CameraPose absolute = pose;
      absolute.position.heightMeters += groundMeters;
      const camera::CameraPose looking = camera::lookingAt(ellipsoid, absolute, *target);
      pose.headingRadians = looking.headingRadians;
      pose.pitchRadians = looking.pitchRadians;
    }
    std::optional<double> fov;
    if (key.fovDegrees) fov = geo::degreesToRadians(*key.fovDegrees);
    path.keyframes.push_back(
        {key.timeSeconds, pose, key.heightAboveTerrain, key.sunUnixSeconds, key.ease, target, fov});
  }
  return path;
}

}  // namespace globe::app
