#include "atmosphere/atmosphere.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/exponential.hpp>

namespace globe::atmosphere {
namespace {

constexpr int kTransmittanceSteps = 40;

}  // namespace

Medium mediumAt(const Atmosphere& a, double altitudeMeters) {
  const double h = std::max(altitudeMeters, 0.0);
  const double rayleigh = std::exp(-h / a.rayleighScaleHeightMeters);
  const double mie = std::exp(-h / a.mieScaleHeightMeters);
  const double ozone =
      std::max(0.0, 1.0 - std::abs(h - a.ozoneCentreMeters) / a.ozoneHalfWidthMeters);
  Medium m;
  m.rayleighScattering = a.rayleighScatteringPerMeter * rayleigh;
  m.mieScattering = a.mieScatteringPerMeter * mie;
  m.extinction = m.rayleighScattering + glm::dvec3(a.mieExtinctionPerMeter * mie) +
                 a.ozoneAbsorptionPerMeter * ozone;
  return m;
}

double rayleighPhase(double cosine) {
  return 3.0 / (16.0 * std::numbers::pi) * (1.0 + cosine * cosine);
}

double miePhase(double cosine, double g) {
  const double g2 = g * g;
  const double k = 3.0 / (8.0 * std::numbers::pi) * (1.0 - g2) / (2.0 + g2);
  return k * (1.0 + cosine * cosine) / std::pow(std::max(1.0 + g2 - 2.0 * g * cosine, 1e-9), 1.5);
}

double distanceToSphere(double r, double mu, double radius) {
  const double b = r * mu;
  const double discriminant = b * b - (r * r - radius * radius);
  if (discriminant < 0.0) return -1.0;
  const double root = std::sqrt(discriminant);
  if (r > radius) {  // entering from outside: the near intersection, ahead only
    const double near = -b - root;
    return near >= 0.0 ? near : -1.0;
  }
  return -b + root;
}

bool hitsGround(const Atmosphere& a, double r, double mu) {
  if (mu >= 0.0) return false;
  return r * r * (mu * mu - 1.0) + a.groundRadiusMeters * a.groundRadiusMeters >= 0.0;
}

glm::dvec3 transmittanceToTop(const Atmosphere& a, double r, double mu) {
  if (hitsGround(a, r, mu)) return glm::dvec3(0.0);
  const double length = std::max(distanceToSphere(r, mu, a.topRadiusMeters), 0.0);
  const double step = length / kTransmittanceSteps;
  glm::dvec3 depth(0.0);
  for (int i = 0; i < kTransmittanceSteps; ++i) {
    const double t = (i + 0.5) * step;
    const double radius = std::sqrt(r * r + t * t + 2.0 * r * mu * t);
    depth += mediumAt(a, radius - a.groundRadiusMeters).extinction * step;
  }
  return glm::exp(-depth);
}

}  // namespace globe::atmosphere
