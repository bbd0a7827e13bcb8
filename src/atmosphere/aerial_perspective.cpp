// The flat-air closed form of the optical depth between two heights (aerial_perspective.hpp).
#include "atmosphere/aerial_perspective.hpp"

#include <algorithm>
#include <cmath>

#include <glm/exponential.hpp>

namespace globe::atmosphere {

double exponentialPathMeters(double fromHeightMeters, double toHeightMeters, double lengthMeters,
                             double scaleHeightMeters) {
  const double h0 = std::max(fromHeightMeters, 0.0), h1 = std::max(toHeightMeters, 0.0);
  const double length = std::max(lengthMeters, 0.0);
  const double rise = h1 - h0;
  // Nearly level: the density at the mean height (the closed form divides 0 by 0 there).
  if (std::abs(rise) < 1e-3 * scaleHeightMeters) {
    return length * std::exp(-0.5 * (h0 + h1) / scaleHeightMeters);
  }
  return length * scaleHeightMeters *
         (std::exp(-h0 / scaleHeightMeters) - std::exp(-h1 / scaleHeightMeters)) / rise;
}

glm::dvec3 aerialTransmittance(const Atmosphere& a, double fromHeightMeters,
                               double toHeightMeters, double lengthMeters) {
  const double rayleigh = exponentialPathMeters(fromHeightMeters, toHeightMeters, lengthMeters,
                                                a.rayleighScaleHeightMeters);
  const double mie = exponentialPathMeters(fromHeightMeters, toHeightMeters, lengthMeters,
                                           a.mieScaleHeightMeters);
  return glm::exp(-(a.rayleighScatteringPerMeter * rayleigh +
                    glm::dvec3(a.mieExtinctionPerMeter * mie)));
}

}  // namespace globe::atmosphere
