// What tile selection needs to know about the camera: position, frustum and projection, in ECEF
// metres and double precision.
#pragma once

#include <numbers>

#include <glm/vec3.hpp>

#include "geo/ellipsoid.hpp"
#include "geo/frustum.hpp"

namespace globe::terrain {

struct SelectionView {
  glm::dvec3 cameraEcefMeters{0.0};
  // In ECEF, built by the caller from projection * view computed in double.
  geo::Frustum frustum{};
  double viewportHeightPixels = 1080.0;
  double fovYRadians = std::numbers::pi / 3.0;  // the vertical field of view (60 degrees)
  geo::Ellipsoid ellipsoid = geo::Ellipsoid::wgs84();
};

}  // namespace globe::terrain
