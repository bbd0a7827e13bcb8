// Aerial perspective's closed form (atmosphere/aerial_perspective.hpp) against the optical depth
// integrated step by step over the spherical atmosphere, and what it does to distant ground:
// more blue than red is taken away, more over longer paths and less from higher up.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "atmosphere/aerial_perspective.hpp"
#include "atmosphere/atmosphere.hpp"

namespace globe::atmosphere {
namespace {

// The straight segment from a point `fromHeight` above the ground to one `toHeight` above the
// ground `groundMeters` away along it, integrated in 10 m steps (at least 20,000) over the
// sphere: the heights along the chord are the true ones (the ground curves away).
double sphericalPath(double fromHeight, double toHeight, double groundMeters, double scale) {
  const Atmosphere air;
  const double r = air.groundRadiusMeters;
  const double angle = groundMeters / r;
  const glm::dvec2 from(0.0, r + fromHeight);
  const glm::dvec2 to((r + toHeight) * std::sin(angle), (r + toHeight) * std::cos(angle));
  const double length = glm::length(to - from);
  const int steps = std::max(20000, static_cast<int>(length / 10.0));
  double sum = 0.0;
  for (int i = 0; i < steps; ++i) {
    const glm::dvec2 p = from + (to - from) * ((i + 0.5) / steps);
    sum += std::exp(-(glm::length(p) - r) / scale) * length / steps;
  }
  return sum;
}

double chordLength(double fromHeight, double toHeight, double groundMeters) {
  const double r = Atmosphere{}.groundRadiusMeters, angle = groundMeters / r;
  const glm::dvec2 from(0.0, r + fromHeight);
  const glm::dvec2 to((r + toHeight) * std::sin(angle), (r + toHeight) * std::cos(angle));
  return glm::length(to - from);
}

TEST(AerialPerspective, TheClosedFormFollowsTheSphericalIntegral) {
  const Atmosphere air;
  struct Case {
    double from, to, ground, tolerance;
  };
  // Near the ground over 1..60 km, a climb to a summit, and straight down from orbit.
  for (const Case c : {Case{2.0, 0.0, 1e3, 0.01}, Case{500.0, 100.0, 30e3, 0.02},
                       Case{1500.0, 3000.0, 60e3, 0.05}, Case{3000.0, 0.0, 60e3, 0.05},
                       Case{400e3, 0.0, 0.0, 0.01}, Case{20e6, 0.0, 0.0, 0.01}}) {
    for (const double scale : {air.rayleighScaleHeightMeters, air.mieScaleHeightMeters}) {
      const double expected = sphericalPath(c.from, c.to, c.ground, scale);
      const double closed =
          exponentialPathMeters(c.from, c.to, chordLength(c.from, c.to, c.ground), scale);
      EXPECT_NEAR(closed, expected, c.tolerance * expected + 1e-9)
          << c.from << " m to " << c.to << " m over " << c.ground << " m, H " << scale;
    }
  }
  EXPECT_EQ(exponentialPathMeters(0.0, 0.0, 0.0, 8000.0), 0.0);
  EXPECT_NEAR(exponentialPathMeters(-50.0, -10.0, 1000.0, 8000.0), 1000.0, 1e-9)
      << "below 0 counts as 0";
}

TEST(AerialPerspective, DistantGroundLosesMoreBlueThanRedAndLessFromHigherUp) {
  const Atmosphere air;
  const glm::dvec3 near = aerialTransmittance(air, 2.0, 0.0, 1e3);
  const glm::dvec3 far = aerialTransmittance(air, 2.0, 0.0, 40e3);
  EXPECT_GT(near.b, 0.95);
  EXPECT_LT(far.b, far.g);
  EXPECT_LT(far.g, far.r);
  EXPECT_LT(far.b, 0.4) << "40 km of sea-level air takes most of the blue";
  EXPECT_GT(far.r, 0.6);
  const glm::dvec3 fromAbove = aerialTransmittance(air, 8000.0, 3000.0, 40e3);
  EXPECT_GT(fromAbove.b, far.b) << "thinner air between peaks";
  // Straight down from space: the whole column, Rayleigh's vertical optical depth 8 km · β.
  const glm::dvec3 column = aerialTransmittance(air, 20e6, 0.0, 20e6);
  EXPECT_NEAR(column.b, std::exp(-(33.1e-6 * 8000.0 + 4.44e-6 * 1200.0)), 1e-3);
}

}  // namespace
}  // namespace globe::atmosphere
