// Constants many test files share. One definition here, used through using-declarations, so that
// a unity build (a target's test files compiled as one translation unit) does not see them twice.
#pragma once

#include <cstdint>

#include "geo/ellipsoid.hpp"

namespace globe::test {

inline const geo::Ellipsoid kWgs84 = geo::Ellipsoid::wgs84();
inline constexpr double kDt = 1.0 / 30.0;            // one frame at 30 Hz, seconds
inline constexpr uint32_t kN = 17;                   // vertices per block side
inline constexpr double kClearance = 2.0;            // the collision tests' clearance, metres
inline constexpr double kFovY = 0.7853981633974483;  // 45 degrees, radians

}  // namespace globe::test
