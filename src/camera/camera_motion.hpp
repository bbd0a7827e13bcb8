// One frame's camera motion as the paper splits it: a static jump, a linear move, or an angular
// move about the globe centre; the rotation of a position and the near plane's corners.
#pragma once

#include <array>
#include <string_view>

#include <glm/vec3.hpp>

#include "camera/camera_pose.hpp"
#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::camera {

enum class MotionKind {
  Auto,     // as input: classify from the two positions (classifyMotion)
  None,     // as output: nothing moved this frame
  Jump,     // a static camera set to a new pose (a teleport): refused if it collides
  Linear,   // a straight move (linear velocity and acceleration): slides
  Angular,  // a rotation about the geocentre (orbit, pan; angular velocity): heightened
};
std::string_view toString(MotionKind kind);

// True when the two positions are within 1 um in ECEF (+-180 deg, any longitude at a pole).
bool isSamePosition(const geo::Ellipsoid& ellipsoid, const geo::Cartographic& a,
                    const geo::Cartographic& b);

// Jump when the position does not move (an orientation change) or moves farther than
// jumpDistanceMeters (a teleport); Angular when the geodetic height is unchanged (within 1 um):
// the Oriented Ray turned about the geocentre; Linear otherwise.
MotionKind classifyMotion(const geo::Ellipsoid& ellipsoid, const geo::Cartographic& from,
                          const geo::Cartographic& to, double jumpDistanceMeters);

// The point turned by |rotation| radians about the axis rotation / |rotation| through the
// geocentre (right hand); unchanged for a zero rotation.
glm::dvec3 rotateAboutGeocentre(const glm::dvec3& pointEcefMeters,
                                const glm::dvec3& rotationRadians);

// The frustum's near plane; set it to the renderer's (projectionForHeight gives a quarter of the
// clearance above the terrain: 0.5 m at the default 2 m).
struct NearPlane {
  double nearMeters = 0.5;
  double fovYRadians = 0.7853981633974483;  // 45 deg, PerspectiveProjection's default
  double aspect = 16.0 / 9.0;
};

// The four corners of the near plane as offsets from the eye (ECEF metres): near * forward
// +- near * tan(fovY / 2) * up +- near * tan(fovY / 2) * aspect * right.
std::array<glm::dvec3, 4> nearPlaneCornerOffsets(const CameraFrame& frame,
                                                 const NearPlane& nearPlane);

}  // namespace globe::camera
