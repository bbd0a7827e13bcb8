// Bench-only: geo::ecefToCartographic's Bowring iteration with sqrt(x^2 + y^2) in place of
// std::hypot, to measure what glibc's hypot costs QOTCD (not used by any method).
#pragma once

#include <glm/vec3.hpp>

#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::bench {

// For positions between ~1 m and ~1e150 m from the centre, off the polar axis, on an ellipsoid
// (not a sphere); agrees with geo::ecefToCartographic to ~1e-15 rad and ~1e-8 m.
geo::Cartographic sqrtEcefToCartographic(const geo::Ellipsoid& ellipsoid, const glm::dvec3& ecef);

}  // namespace globe::bench
