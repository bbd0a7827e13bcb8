// Deterministic test holes for the fill benchmark: round, blobby 4-connected regions of a given
// diameter, placed only on valid land of a real tile so that the removed samples are truth.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "conditioning/dem_grid.hpp"

namespace globe::bench_fill {

struct Hole {
  int64_t centreRow = 0, centreColumn = 0;
  std::vector<size_t> samples;  // grid indices, ascending; 4-connected, contains the centre
};

struct HolePlacement {
  uint64_t seed = 1;
  int64_t edgeMarginSamples = 4;   // no hole sample closer than this to the tile edge
  int64_t gapSamples = 3;          // holes of one set stay this far apart (Chebyshev)
  int64_t attemptsPerHole = 4000;  // random centres tried per wanted hole before giving up
};

// A blob of nominal diameter diameterSamples around the origin: the samples within a radius
// that wobbles by up to about ±30% with direction (three random harmonics), reduced to the
// 4-connected part containing the origin. Offsets as (row, column) pairs.
struct Offset {
  int64_t row = 0, column = 0;
};
std::vector<Offset> blobOffsets(double diameterSamples, uint64_t seed);

// Land: a valid sample above 0 m (no-data -9999 and sea at 0 m excluded).
constexpr bool isLand(int16_t sample) { return sample > 0; }

// Up to `count` holes of one diameter: every sample of a hole and of its 8-neighbour ring is
// land, no hole comes within placement.gapSamples of another or within edgeMarginSamples of the
// tile edge. The same grid, diameter, count and placement give the same holes, on every
// platform (own integer-to-double mapping, no std distributions). Fewer holes come back when
// the land has no room for more.
std::vector<Hole> placeHoles(const conditioning::DemGrid& grid, double diameterSamples,
                             size_t count, const HolePlacement& placement);

// One flag per grid sample: 1 inside any of the holes.
std::vector<uint8_t> voidMask(const conditioning::DemGrid& grid, const std::vector<Hole>& holes);

}  // namespace globe::bench_fill
