// How far a filled grid is from the truth over the hole samples, and whether an interpolating
// fill stayed within each hole's border range.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "conditioning/dem_grid.hpp"
#include "tools/bench_fill/hole_generator.hpp"

namespace globe::bench_fill {

struct ErrorSummary {
  size_t samples = 0;
  double rmseMeters = 0;
  double p99Meters = 0;   // of |filled - truth|, nearest rank
  double maxMeters = 0;   // of |filled - truth|
  double biasMeters = 0;  // mean of filled - truth
};

// Over every sample of every hole.
ErrorSummary summariseErrors(const std::vector<int16_t>& filled, const std::vector<int16_t>& truth,
                             const std::vector<Hole>& holes);

// Hole samples whose filled value lies outside [min, max] of that hole's border (the samples
// 4-adjacent to the hole and not in it), and valid samples outside the holes that the fill
// changed (no-data samples are left out: GDAL fills them too).
struct BorderCheck {
  size_t outsideBorderRange = 0;
  size_t holeSamples = 0;
  size_t changedOutsideHoles = 0;
};
BorderCheck checkBorderRange(const conditioning::DemGrid& filled,
                             const conditioning::DemGrid& truth, const std::vector<Hole>& holes,
                             const std::vector<uint8_t>& isVoid);

}  // namespace globe::bench_fill
