// Conditions one source's samples before tiling: sea told from voids and from the outside of the
// source's footprint (sea_classification), sea written as water (its depth kept where measured),
// voids filled (void_fill), and the coarser surface bent to meet the footprint's edge outside it
// (footprint_bend). The footprint's own samples are never altered. Deterministic.
#pragma once

#include <cstdint>

#include "conditioning/coarser_sources.hpp"
#include "conditioning/dem_grid.hpp"
#include "conditioning/footprint_bend.hpp"
#include "conditioning/void_fill.hpp"

namespace globe::conditioning {

struct ConditionOptions {
  FillOptions fill;
  double bendMarginDegrees = 0;  // over which the coarser surface bends to the footprint's edge
  bool noDataIsWater = false;    // the source's no data is an explicit water code (GTOPO30's)
};

struct ConditionStats {
  uint64_t samples = 0;
  uint64_t noDataSamples = 0;  // in the source as given
  uint64_t seaSamples = 0;     // written as water (no data under coarser water, or measured sea)
  uint64_t voidSamples = 0;    // no data inside the footprint (filled)
  FillStats fill;
  uint64_t outsideSamples = 0;  // outside the footprint: the coarser surface, bent to its edge
  bool allNoData() const { return samples > 0 && noDataSamples == samples; }
};

// coarser: the already conditioned coarser sources, or nullptr when there are none.
ConditionStats conditionGrid(DemGrid& grid, const CoarserSources* coarser,
                             const ConditionOptions& options);

}  // namespace globe::conditioning
