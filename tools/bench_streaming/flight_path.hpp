// The benchmark's scripted flight: a low spiral over Mount Fuji, a world circuit along the
// great circle through Fuji and England, and a second, smaller loop over Fuji.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace globe::bench {

struct CameraSample {
  double longitudeRadians;
  double latitudeRadians;
  double heightMeters;  // above the ground, which picks the finest level wanted
  std::string leg;      // which part of the flight
};

// stepsPerLeg samples for each of the three legs, in flight order.
std::vector<CameraSample> scriptedFlight(size_t stepsPerLeg);

}  // namespace globe::bench
