// Fills voids (no-data samples inside land) of a DEM grid:
//  - small voids, and voids no coarser source covers, by harmonic interpolation from the void's
//    border (the smoothest surface through the border: every value within the border's range);
//  - large voids by the delta-surface method: the next coarser source, shifted by the harmonic
//    interpolation of (fine - coarse) on the border, so it meets the border exactly.
// Deterministic: the same grid and sources give the same bytes.
#pragma once

#include <cstdint>
#include <vector>

#include "dem/coarser_sources.hpp"
#include "dem/dem_grid.hpp"

namespace globe::dem {

struct FillOptions {
  // A void of more samples than this is filled from the coarser source when one covers all of it.
  int64_t smallVoidMaxSamples = 64;
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

}  // namespace globe::dem
