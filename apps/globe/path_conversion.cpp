// io::CameraPathFile → camera::CameraPath: degrees to radians, terrain-relative heights resolved.
#include "apps/globe/path_conversion.hpp"

namespace globe::app {

Result<camera::CameraPath> toCameraPath(const camera::CameraPathFile& file,
                                        const TerrainHeightFunction& terrainHeight) {
  const auto interpolation = camera::parsePathInterpolation(file.interpolation);
  if (!interpolation) {
    return makeError("interpolation '" + file.interpolation + "' is not linear or smooth");
  }
  camera::CameraPath path;
  path.interpolation = *interpolation;
  for (size_t k = 0; k < file.keyframes.size(); ++k) {
    const camera::PathKeyframe& key = file.keyframes[k];
    camera::CameraPose pose =
        camera::CameraPose::fromDegrees(key.longitudeDegrees, key.latitudeDegrees, key.heightMeters,
                                        key.headingDegrees, key.pitchDegrees, key.rollDegrees);
    if (key.heightAboveTerrain) {
      // Kept above the terrain (camera::samplePath adds it where the path is); read here once
      // so that a terrain that cannot be read is an error naming the keyframe.
      auto ground = terrainHeight(pose.position.longitudeRadians, pose.position.latitudeRadians);
      if (!ground) {
        return makeError("keyframes[" + std::to_string(k) +
                         "]: the terrain height: " + ground.error());
      }
    }
    path.keyframes.push_back({key.timeSeconds, pose, key.heightAboveTerrain, key.sunUnixSeconds});
  }
  return path;
}

}  // namespace globe::app
