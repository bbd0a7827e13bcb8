// Fills voids (no-data samples inside land) of a DEM grid:
//  - small voids, and voids no coarser source covers, by interpolation from the void's border:
//    minimum curvature in tension up to a few thousand samples, harmonic beyond (every value
//    within the border's range either way);
//  - large voids by the delta-surface method: the next coarser source, shifted by the harmonic
//    interpolation of (fine - coarse) on the border, so it meets the border exactly.
// Deterministic: the same grid and sources give the same bytes.
#pragma once

#include <cstdint>
#include <vector>

#include "conditioning/coarser_sources.hpp"
#include "conditioning/dem_grid.hpp"

namespace globe::conditioning {

struct FillOptions {
  // A void of more samples than this is filled from the coarser source when one covers all of it.
  int64_t smallVoidMaxSamples = 64;
  // Voids up to this size are refined from the harmonic fill to minimum curvature in tension
  // (0: never). Larger ones gain little from it (measured: 1-2 % RMSE) at 10-100× the time.
  int64_t minimumCurvatureMaxSamples = 4096;
  // The tension T: 0.25 was the best balance over holes of 3 to 50 samples across
  // (docs/performance/fill-accuracy.md); 0 bulges in 50-sample holes, 0.5 loses a tenth on small ones.
  double tension = 0.25;
};

struct FillStats {
  uint64_t voids = 0;                // connected void regions
  uint64_t interpolatedSamples = 0;  // filled from the border alone
  uint64_t fromCoarserSamples = 0;   // filled from the coarser source (delta surface)
  uint64_t unfilledSamples = 0;      // a void with no border (the whole grid is void)
};

// Fills the samples with isVoid[i] set (one flag per sample); each void is a 4-connected region.
// A void with no valid border sample is filled from the coarser source if it covers it, else
// left as it is.
FillStats fillVoids(DemGrid& grid, const std::vector<uint8_t>& isVoid,
                    const CoarserSources* coarser, const FillOptions& options = {});

}  // namespace globe::conditioning
