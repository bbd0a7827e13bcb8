// A camera pose on the globe (position + heading/pitch/roll) and the ECEF frame and matrices it
// gives, all in double so the view is exact at Earth radius.
#pragma once

#include <glm/glm.hpp>
#include <optional>

#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::camera {

// Heading 0 = north, clockwise (90° = east); pitch 0 = the horizon, −90° = straight down; roll
// turns the image clockwise about the view direction. Height is above the ellipsoid.
struct CameraPose {
  geo::Cartographic position;
  double headingRadians = 0;
  double pitchRadians = 0;
  double rollRadians = 0;

  static CameraPose fromDegrees(double longitudeDegrees, double latitudeDegrees,
                                double heightMeters, double headingDegrees = 0,
                                double pitchDegrees = -90, double rollDegrees = 0);
  bool isFinite() const;
};

// Exactly the same pose, field by field (no tolerance: used to tell "moved" from "not moved").
bool samePose(const CameraPose& a, const CameraPose& b);

// Orthonormal camera axes in ECEF.
struct CameraFrame {
  glm::dvec3 positionEcefMeters;
  glm::dvec3 forward;
  glm::dvec3 up;
  glm::dvec3 right;
};

CameraFrame cameraFrame(const geo::Ellipsoid& ellipsoid, const CameraPose& pose);

// East, north, up unit vectors at a position (well defined at the poles: east follows longitude).
struct EastNorthUp {
  glm::dvec3 east, north, up;
};
EastNorthUp eastNorthUp(const geo::Ellipsoid& ellipsoid, const geo::Cartographic& position);

// World (ECEF) → camera, OpenGL convention (the camera looks down −z).
glm::dmat4 viewMatrix(const CameraFrame& frame);

struct PerspectiveProjection {
  double fovYRadians = 0.7853981633974483;  // 45°
  double aspect = 16.0 / 9.0;
  double nearMeters = 0.5;
  double farMeters = 1e8;
};
glm::dmat4 projectionMatrix(const PerspectiveProjection& projection);

// Near and far planes: near a fraction of the clearance above the terrain (terrain 0.5 m away
// is still drawn), far past the horizon of the highest mountain seen from this height.
PerspectiveProjection projectionForHeight(double heightAboveEllipsoidMeters,
                                          double heightAboveTerrainMeters, double fovYRadians,
                                          double aspect, const geo::Ellipsoid& ellipsoid);

}  // namespace globe::camera
