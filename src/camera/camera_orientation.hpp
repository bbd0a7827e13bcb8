// A camera's orientation as an ECEF quaternion (independent of where the pose's local frame
// is), back to heading/pitch/roll at a position, and the quaternion log/exp of rotation vectors.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "camera/camera_pose.hpp"
#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::camera {

// The rotation taking camera axes (x right, y up, z back: OpenGL) to ECEF: columns right, up,
// -forward of cameraFrame(pose).
glm::dquat orientationEcef(const geo::Ellipsoid& ellipsoid, const CameraPose& pose);

// The pose at `position` whose cameraFrame has the orientation's axes. Heading in (-pi, pi],
// pitch in [-pi/2, pi/2]; looking straight down or up (heading and roll then turn the image
// about the same axis) the roll is 0 and the heading carries the turn.
CameraPose poseFromOrientation(const geo::Ellipsoid& ellipsoid, const geo::Cartographic& position,
                               const glm::dquat& orientation);

// The rotation vector (axis * angle, angle in [0, pi]: the shortest arc) of a unit quaternion,
// and back. expRotation(logRotation(q)) is q or -q (the same rotation).
glm::dvec3 logRotation(const glm::dquat& rotation);
glm::dquat expRotation(const glm::dvec3& rotationRadians);

}  // namespace globe::camera
