// Test helper: random points of a BoundingRegion (corners and edges included on purpose).
#pragma once

#include <random>

#include <glm/vec3.hpp>

#include "geo/bounding_region.hpp"
#include "geo/ecef.hpp"

namespace globe::geo::testing {

// A fraction in [0, 1] that is exactly 0 or 1 a quarter of the time, so edges get sampled.
inline double fractionWithEdges(std::mt19937_64& rng) {
  const double u = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
  if (u < 0.125) return 0.0;
  if (u < 0.25) return 1.0;
  return std::uniform_real_distribution<double>(0.0, 1.0)(rng);
}

inline glm::dvec3 sampleRegionPoint(std::mt19937_64& rng, const BoundingRegion& region,
                                    const Ellipsoid& ellipsoid) {
  const GlobeRectangle& r = region.rectangle;
  const double lon = r.westRadians + fractionWithEdges(rng) * r.widthRadians();
  const double lat = r.southRadians + fractionWithEdges(rng) * r.heightRadians();
  const double h =
      region.minimumHeightMeters +
      fractionWithEdges(rng) * (region.maximumHeightMeters - region.minimumHeightMeters);
  return cartographicToEcef(ellipsoid, {std::min(lon, r.eastRadians), std::min(lat, r.northRadians),
                                        std::min(h, region.maximumHeightMeters)});
}

// Random heights for terrain: minimum in [-11 km, 5 km], range up to 9 km, sometimes flat.
inline void randomHeights(std::mt19937_64& rng, double& minimum, double& maximum) {
  minimum = std::uniform_real_distribution<double>(-11000.0, 5000.0)(rng);
  const double u = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
  maximum = u < 0.1 ? minimum : minimum + std::uniform_real_distribution<double>(0.0, 9000.0)(rng);
}

}  // namespace globe::geo::testing
