// Pointing the camera at a point: the heading and pitch that put a target at the frame's centre
// (roll kept), and the camera of a KML LookAt (the point, the heading, the tilt and the range).
#pragma once

#include <optional>

#include <glm/vec3.hpp>

#include "camera/camera_pose.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::camera {

// `pose` turned to look at targetEcefMeters: heading and pitch from the local east-north-up frame
// at its position, roll as it was. Straight above or below the target (no horizontal direction)
// the heading is kept; a target at the camera's own position changes nothing.
CameraPose lookingAt(const geo::Ellipsoid& ellipsoid, CameraPose pose,
                     const glm::dvec3& targetEcefMeters);

// Where a KML LookAt puts the camera: `rangeMeters` from the target, back along the view that
// `headingDegrees` and `tiltDegrees` (0 straight down, 90 level) give, in the target's
// east-north-up frame; the pose looking at it (pitch = tilt − 90°, roll 0).
CameraPose cameraOfLookAt(const geo::Ellipsoid& ellipsoid, const geo::Cartographic& target,
                          double headingDegrees, double tiltDegrees, double rangeMeters);

}  // namespace globe::camera
