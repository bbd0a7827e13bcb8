// Precomputed tables of the atmosphere (atmosphere.hpp), built once on the CPU: the transmittance
// to the top of the air from any radius and zenith cosine, and Hillaire's (2020) multiple
// scattering of all orders as a function of radius and the Sun's zenith cosine (the light that
// second and later bounces add, with the ground's albedo), both read with bilinear filtering.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "atmosphere/atmosphere.hpp"

namespace globe::atmosphere {

class SkyTables {
 public:
  explicit SkyTables(const Atmosphere& atmosphere);
  // The tables of the default Atmosphere, built on first use (thread-safe).
  static const SkyTables& earth();

  const Atmosphere& atmosphere() const { return atmosphere_; }
  glm::dvec3 transmittance(double r, double mu) const;
  glm::dvec3 multipleScattering(double r, double sunMu) const;

 private:
  struct Table {
    int columns = 0, rows = 0;  // columns: cosine in [-1, 1]; rows: radius ground → top
    std::vector<glm::dvec3> values;
    glm::dvec3 at(double u, double v) const;  // u, v in [0, 1], bilinear
  };
  glm::dvec3 multipleScatteringAt(double r, double sunMu) const;
  double rowOf(double r) const;

  Atmosphere atmosphere_;
  Table transmittance_;
  Table multiple_;
};

}  // namespace globe::atmosphere
