// Conditions one source's samples before tiling: sea told from voids (sea_classification), sea
// written as water (its depth kept where measured), voids filled (void_fill), and the source
// eased into the coarser ones at its edges (source_blend). Deterministic.
#pragma once

#include <cstdint>

#include "dem/coarser_sources.hpp"
#include "dem/dem_grid.hpp"
#include "dem/source_blend.hpp"
#include "dem/void_fill.hpp"

namespace globe::dem {

struct ConditionOptions {
  FillOptions fill;
  double blendMarginDegrees = 0;   // 0: no blend
  CoverageTest sameOrFinerCovers;  // for the blend; empty: no other source is as fine
};

struct ConditionStats {
  uint64_t samples = 0;
  uint64_t noDataSamples = 0;  // in the source as given
  uint64_t seaSamples = 0;     // written as water (no data or measured at or below 0 m)
  uint64_t voidSamples = 0;    // no data inside land
  FillStats fill;
  uint64_t blendedSamples = 0;
  bool allNoData() const { return samples > 0 && noDataSamples == samples; }
};

// coarser: the already conditioned coarser sources, or nullptr when there are none.
ConditionStats conditionGrid(DemGrid& grid, const CoarserSources* coarser,
                             const ConditionOptions& options);

}  // namespace globe::dem
