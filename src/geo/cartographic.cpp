// Longitude wrapping.
#include "geo/cartographic.hpp"

#include <cmath>

namespace globe::geo {

double wrapLongitudeRadians(double longitudeRadians) {
  constexpr double pi = std::numbers::pi;
  if (longitudeRadians >= -pi && longitudeRadians <= pi) return longitudeRadians;
  // remainder() is exact and returns a value in [-pi, pi] for the divisor 2*pi (2*pi is exact).
  return std::remainder(longitudeRadians, 2.0 * pi);
}

}  // namespace globe::geo
