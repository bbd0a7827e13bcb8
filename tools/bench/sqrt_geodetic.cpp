// The same steps as geo/ecef.cpp's Bowring iteration, normalising with sqrt instead of hypot.
#include "tools/bench/sqrt_geodetic.hpp"

#include <algorithm>
#include <cmath>

namespace globe::bench {
namespace {

struct Direction {
  double cos;
  double sin;
};

Direction direction(double c, double s) {
  const double length = std::sqrt(c * c + s * s);
  return {c / length, s / length};
}

}  // namespace

geo::Cartographic sqrtEcefToCartographic(const geo::Ellipsoid& ellipsoid, const glm::dvec3& ecef) {
  const double a = ellipsoid.semiMajorAxisMeters;
  const double b = ellipsoid.semiMinorAxisMeters;
  const double p = std::sqrt(ecef.x * ecef.x + ecef.y * ecef.y);
  const double z = ecef.z;
  const double e2 = 1.0 - (b / a) * (b / a);
  const double ep2 = (a / b) * (a / b) - 1.0;
  Direction beta = direction(p, z * (a / b));
  Direction lat{1.0, 0.0};
  for (int iteration = 0; iteration < 6; ++iteration) {
    const double numerator = z + ep2 * b * beta.sin * beta.sin * beta.sin;
    const double denominator = std::max(0.0, p - e2 * a * beta.cos * beta.cos * beta.cos);
    const Direction next = direction(denominator, numerator);
    const bool converged = iteration > 0 && std::abs(next.sin - lat.sin) <= 1e-14 &&
                           std::abs(next.cos - lat.cos) <= 1e-14;
    lat = next;
    if (converged) break;
    beta = direction(a * lat.cos, b * lat.sin);
  }
  const double height = p * lat.cos + z * lat.sin - a * std::sqrt(1.0 - e2 * lat.sin * lat.sin);
  return {std::atan2(ecef.y, ecef.x), std::atan2(lat.sin, lat.cos), height};
}

}  // namespace globe::bench
