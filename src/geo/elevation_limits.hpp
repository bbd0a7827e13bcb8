// The elevations a path or track on or above the Earth can have: below the deepest trench to the
// edge of space. A file's elevation outside them (1e308, NaN: written where a device had none)
// is read as not given.
#pragma once

namespace globe::geo {

inline constexpr double kLowestPathElevationMeters = -12'000;
inline constexpr double kHighestPathElevationMeters = 100'000;

// False for NaN too.
inline bool isPossibleElevationMeters(double meters) {
  return meters >= kLowestPathElevationMeters && meters <= kHighestPathElevationMeters;
}

}  // namespace globe::geo
