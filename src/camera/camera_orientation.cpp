// Orientation quaternions of camera poses and their rotation-vector log/exp.
#include "camera/camera_orientation.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

namespace globe::camera {

glm::dquat orientationEcef(const geo::Ellipsoid& ellipsoid, const CameraPose& pose) {
  const CameraFrame frame = cameraFrame(ellipsoid, pose);
  const glm::dmat3 axes(frame.right, frame.up, -frame.forward);
  return glm::normalize(glm::quat_cast(axes));
}

CameraPose poseFromOrientation(const geo::Ellipsoid& ellipsoid, const geo::Cartographic& position,
                               const glm::dquat& orientation) {
  const glm::dmat3 axes = glm::mat3_cast(glm::normalize(orientation));
  const glm::dvec3 up = axes[1], forward = -axes[2];
  const EastNorthUp enu = eastNorthUp(ellipsoid, position);
  const double fe = glm::dot(forward, enu.east), fn = glm::dot(forward, enu.north);
  const double fu = glm::dot(forward, enu.up);
  const double horizontalLength = std::sqrt(fe * fe + fn * fn);
  CameraPose pose;
  pose.position = position;
  pose.pitchRadians = std::atan2(fu, horizontalLength);
  if (horizontalLength > 1e-12) {
    pose.headingRadians = std::atan2(fe, fn);
    // cameraFrame's unrolled axes for this heading and pitch; the roll turns up towards right.
    const double sh = std::sin(pose.headingRadians), ch = std::cos(pose.headingRadians);
    const double sp = std::sin(pose.pitchRadians), cp = std::cos(pose.pitchRadians);
    const glm::dvec3 horizontal = sh * enu.east + ch * enu.north;
    const glm::dvec3 up0 = -sp * horizontal + cp * enu.up;
    const glm::dvec3 right0 = glm::cross(forward, up0);
    pose.rollRadians = std::atan2(glm::dot(up, right0), glm::dot(up, up0));
  } else {
    // Straight down, the unrolled up is the heading direction; straight up, its opposite.
    const double sign = fu < 0 ? 1.0 : -1.0;
    pose.headingRadians = std::atan2(sign * glm::dot(up, enu.east), sign * glm::dot(up, enu.north));
    pose.rollRadians = 0;
  }
  return pose;
}

glm::dvec3 logRotation(const glm::dquat& rotation) {
  glm::dquat q = glm::normalize(rotation);
  if (q.w < 0) q = -q;  // the shortest arc: angle <= pi
  const glm::dvec3 v(q.x, q.y, q.z);
  const double s = glm::length(v);
  if (s < 1e-12) return 2.0 * v;
  return (2.0 * std::atan2(s, q.w) / s) * v;
}

glm::dquat expRotation(const glm::dvec3& rotationRadians) {
  const double angle = glm::length(rotationRadians);
  if (angle < 1e-12) {
    return glm::normalize(
        glm::dquat(1.0, rotationRadians.x / 2, rotationRadians.y / 2, rotationRadians.z / 2));
  }
  const glm::dvec3 v = (std::sin(angle / 2) / angle) * rotationRadians;
  return glm::dquat(std::cos(angle / 2), v.x, v.y, v.z);
}

}  // namespace globe::camera
