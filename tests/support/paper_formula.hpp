// The paper's formula (1), implemented literally FOR COMPARISON ONLY: it exists so that a test
// can demonstrate its flaws against ecefToCartographic. Do not use it for real conversions.
#pragma once

#include <glm/vec3.hpp>

namespace globe::testing {

struct PaperSphereCoordinates {
  double longitudeRadians;
  double latitudeRadians;
  double radiusMeters;
};

// Formula (1) in the paper's OpenGL y-up frame: L = atan(x/z), B = asin(y/|p|), R = |p|.
// Flaws: atan(x/z) only returns (-pi/2, pi/2), so longitudes beyond +-90 deg come out off by pi
// (and z = 0 divides by zero); asin(y/R) is ill-conditioned near the poles, where its argument
// is ~1 and rounding to the nearest double costs ~1e-8 rad; the origin gives NaN.
PaperSphereCoordinates paperFormula1(const glm::dvec3& yUpMeters);

// Our ECEF to the paper's y-up frame: x_gl = y_ecef, y_gl = z_ecef, z_gl = x_ecef, chosen so
// that the paper's L = atan(x/z) is the longitude and its B the latitude.
glm::dvec3 ecefToPaperYUp(const glm::dvec3& ecefMeters);

}  // namespace globe::testing
