#include "atmosphere/sky_tables.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

namespace globe::atmosphere {
namespace {

constexpr int kTransmittanceColumns = 256, kTransmittanceRows = 64;
constexpr int kMultipleColumns = 32, kMultipleRows = 16;
constexpr int kSphereDirections = 8;  // per axis: 64 directions over the sphere
constexpr int kMultipleSteps = 20;

}  // namespace

glm::dvec3 SkyTables::Table::at(double u, double v) const {
  const double x = std::clamp(u, 0.0, 1.0) * (columns - 1);
  const double y = std::clamp(v, 0.0, 1.0) * (rows - 1);
  const int x0 = std::min(static_cast<int>(x), columns - 2);
  const int y0 = std::min(static_cast<int>(y), rows - 2);
  const double fx = x - x0, fy = y - y0;
  auto value = [&](int c, int r) { return values[static_cast<size_t>(r) * columns + c]; };
  return (value(x0, y0) * (1 - fx) + value(x0 + 1, y0) * fx) * (1 - fy) +
         (value(x0, y0 + 1) * (1 - fx) + value(x0 + 1, y0 + 1) * fx) * fy;
}

double SkyTables::rowOf(double r) const {
  return (r - atmosphere_.groundRadiusMeters) /
         (atmosphere_.topRadiusMeters - atmosphere_.groundRadiusMeters);
}

SkyTables::SkyTables(const Atmosphere& atmosphere) : atmosphere_(atmosphere) {
  const double span = atmosphere.topRadiusMeters - atmosphere.groundRadiusMeters;
  transmittance_ = {kTransmittanceColumns, kTransmittanceRows, {}};
  for (int row = 0; row < kTransmittanceRows; ++row) {
    const double r = atmosphere.groundRadiusMeters + span * row / (kTransmittanceRows - 1);
    for (int column = 0; column < kTransmittanceColumns; ++column) {
      const double mu = -1.0 + 2.0 * column / (kTransmittanceColumns - 1);
      transmittance_.values.push_back(
          transmittanceToTop(atmosphere, std::max(r, atmosphere.groundRadiusMeters + 1.0), mu));
    }
  }
  multiple_ = {kMultipleColumns, kMultipleRows, {}};
  for (int row = 0; row < kMultipleRows; ++row) {
    const double r = atmosphere.groundRadiusMeters + 1.0 + (span - 2.0) * row / (kMultipleRows - 1);
    for (int column = 0; column < kMultipleColumns; ++column) {
      const double sunMu = -1.0 + 2.0 * column / (kMultipleColumns - 1);
      multiple_.values.push_back(multipleScatteringAt(r, sunMu));
    }
  }
}

const SkyTables& SkyTables::earth() {
  static const SkyTables tables{Atmosphere{}};
  return tables;
}

glm::dvec3 SkyTables::transmittance(double r, double mu) const {
  if (hitsGround(atmosphere_, r, mu)) return glm::dvec3(0.0);
  return transmittance_.at(0.5 * (mu + 1.0), rowOf(r));
}

glm::dvec3 SkyTables::multipleScattering(double r, double sunMu) const {
  return multiple_.at(0.5 * (sunMu + 1.0), rowOf(r));
}

// Hillaire 2020, section 5.5: from a point, the second-order light L2 gathered over the sphere
// (isotropic phase) and the fraction f that the medium scatters back to it; all orders sum to
// L2 / (1 - f). The Sun comes from zenith cosine sunMu in the x-z plane.
glm::dvec3 SkyTables::multipleScatteringAt(double r, double sunMu) const {
  const Atmosphere& a = atmosphere_;
  const glm::dvec3 sun(std::sqrt(std::max(0.0, 1.0 - sunMu * sunMu)), 0.0, sunMu);
  const double isotropic = 1.0 / (4.0 * std::numbers::pi);
  glm::dvec3 secondOrder(0.0), transfer(0.0);
  const int n = kSphereDirections;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double cosTheta = 1.0 - 2.0 * (i + 0.5) / n;  // uniform over the sphere
      const double phi = 2.0 * std::numbers::pi * (j + 0.5) / n;
      const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
      const glm::dvec3 d(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
      const bool ground = hitsGround(a, r, cosTheta);
      const double length = ground ? distanceToSphere(r, cosTheta, a.groundRadiusMeters)
                                   : distanceToSphere(r, cosTheta, a.topRadiusMeters);
      const double step = std::max(length, 0.0) / kMultipleSteps;
      glm::dvec3 throughput(1.0), light(0.0), scattered(0.0);
      for (int k = 0; k < kMultipleSteps; ++k) {
        const double t = (k + 0.5) * step;
        const glm::dvec3 p = glm::dvec3(0.0, 0.0, r) + t * d;
        const double radius = std::sqrt(glm::dot(p, p));
        const Medium m = mediumAt(a, radius - a.groundRadiusMeters);
        const glm::dvec3 scattering = m.rayleighScattering + glm::dvec3(m.mieScattering);
        const glm::dvec3 stepTransmittance = glm::exp(-m.extinction * step);
        const glm::dvec3 toSun = transmittance(radius, glm::dot(p, sun) / radius);
        // Energy-conserving integration of the step (Hillaire 2020, section 5.6.3).
        const glm::dvec3 safeExtinction = glm::max(m.extinction, glm::dvec3(1e-12));
        const glm::dvec3 integral = (glm::dvec3(1.0) - stepTransmittance) / safeExtinction;
        light += throughput * scattering * toSun * isotropic * integral;
        scattered += throughput * scattering * integral;
        throughput *= stepTransmittance;
      }
      if (ground) {  // the lit ground reflects (Lambert) what reaches it
        const glm::dvec3 p = glm::dvec3(0.0, 0.0, r) + length * d;
        const double radius = glm::length(p);
        const double sunCosine = std::max(glm::dot(p / radius, sun), 0.0);
        light += throughput * transmittance(radius, glm::dot(p, sun) / radius) * sunCosine *
                 a.groundAlbedo / std::numbers::pi;
      }
      const double weight = 1.0 / (n * n);  // each direction's share of the sphere
      secondOrder += light * weight;
      transfer += scattered * isotropic * 4.0 * std::numbers::pi * weight;
    }
  }
  return secondOrder / (glm::dvec3(1.0) - glm::min(transfer, glm::dvec3(0.999)));
}

}  // namespace globe::atmosphere
