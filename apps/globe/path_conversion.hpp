// A path file's keyframes (degrees, heights maybe above the terrain) as a camera path (radians,
// heights above the ellipsoid): the one place where the two meet.
#pragma once

#include <functional>

#include "camera/camera_path.hpp"
#include "camera/camera_path_file.hpp"
#include "core/result.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::app {

// The terrain height (metres) under a position in radians, for keyframes above the terrain.
using TerrainHeightFunction = std::function<Result<double>(double, double)>;

// Converts every keyframe; aboveTerrain heights stay above the terrain (camera::CameraKeyframe:
// samplePath adds the terrain along the path). A keyframe's target is resolved to ECEF (its
// aboveTerrain height on the terrain there) and the keyframe turned to look at it. Errors: an
// unknown interpolation, a failing terrain lookup at an aboveTerrain keyframe or target (named
// with the keyframe).
Result<camera::CameraPath> toCameraPath(const camera::CameraPathFile& file,
                                        const TerrainHeightFunction& terrainHeight,
                                        const geo::Ellipsoid& ellipsoid);

}  // namespace globe::app
