// How faithfully a pyramid draws one of its sources at that source's finest level:
//  - |drawn − source| at the lattice vertices whose 2×2 source samples are all land (measured
//    above 0 m; the source's bilinear surface there), inside and in the band along the source's
//    edges: the tiler must not alter a source inside its footprint;
//  - the steps across the footprint's edge (into the source's no data reaching its border, or
//    beyond its rectangle) against the source's own steps near them: no wall;
//  - the vertices over the source's no data (the nearest sample, with no measured sample at or
//    below 0 m among the 2×2, where the coast rule decides) drawn as water where the
//    coarser surface is above 0 m or no coarser source covers them: sea only where something
//    says sea.
// Written apart from the tiler's code (its own lattice, bilinear and footprint) to check it.
#pragma once

#include <cstdint>

#include "conditioning/dem_grid.hpp"
#include "streaming/tile_store.hpp"

namespace globe::fidelity {

struct DifferenceStats {
  uint64_t count = 0;
  double p95Meters = 0;
  double maxMeters = 0;
};

struct SourceFidelity {
  uint32_t level = 0;
  DifferenceStats inside;    // farther than the band from the rectangle's edges
  DifferenceStats edgeBand;  // within the band
  // Neighbouring vertices, one on the footprint and one off it (outside the rectangle, or over
  // no data reaching the border).
  uint64_t edgePairs = 0;
  double worstStepAcrossMeters = 0;
  double sourceP999StepMeters = 0;  // between neighbouring footprint vertices
  // Edge pairs whose step exceeds 1.5× the largest step between the source's own neighbouring
  // samples within 5 samples (a wall); the worst ratio of step to that bound.
  uint64_t stepsOverLocalBound = 0;
  double worstLocalStepRatio = 0;
  uint64_t noDataVertices = 0;            // over no data (see above)
  uint64_t noDataDrawnAsSeaOverLand = 0;  // of those, water where nothing says sea: must be 0
  bool noDataIsWater = false;             // the source's no data is its water code: not counted
};

// source: the raster as given (no data = -9999); coarser: the coarser sources as given (finest
// first; empty: none), for the sea check; peers: the equally fine ones (their joins are not
// edges); noDataIsWater: the source's no data is an explicit water code (GTOPO30's ocean mask),
// so no sea check. Level: the source's finest level.
Result<SourceFidelity> measureSourceFidelity(
    streaming::TileStore& store, uint32_t level, const conditioning::DemGrid& source,
    const std::vector<const conditioning::DemGrid*>& coarser,
    const std::vector<const conditioning::DemGrid*>& peers, bool noDataIsWater,
    double edgeBandDegrees = 0.1);

}  // namespace globe::fidelity
