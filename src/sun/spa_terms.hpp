// The tables of the Solar Position Algorithm (spa_terms.cpp): data, read by solar_position.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace globe::sun::spa {

// A·cos(B + C·JME), JME in Julian millennia from J2000 (terrestrial time).
struct PeriodicTerm {
  double a, b, c;
};

// L = Σi Li·JME^i with Li the sum of kLongitudeTerms[i] (1e-8 radians); B and R alike.
extern const std::span<const PeriodicTerm> kLongitudeTerms[6];
extern const std::span<const PeriodicTerm> kLatitudeTerms[2];
extern const std::span<const PeriodicTerm> kRadiusTerms[5];

// Multipliers of the five mean elements X0..X4 and the coefficients a, b, c, d: nutation in
// longitude Σ (a + b·JCE)·sin(Σ Xj·Yj), in obliquity Σ (c + d·JCE)·cos(Σ Xj·Yj), in 0.0001″.
struct NutationTerm {
  int8_t y[5];
  double a, b, c, d;
};
inline constexpr size_t kNutationTermCount = 63;
extern const NutationTerm kNutationTerms[kNutationTermCount];

}  // namespace globe::sun::spa
