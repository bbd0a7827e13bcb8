// No walls between sources: where a finer source ends inside a coarser one, its land samples are
// eased into the coarser surface over a margin, so at its edge it meets the coarser source and
// the step across the boundary is spread over the margin. Edges where an equally fine (or finer)
// source continues, or where no coarser source lies beyond, are left alone.
#pragma once

#include <cstdint>
#include <functional>

#include "dem/coarser_sources.hpp"
#include "dem/dem_grid.hpp"

namespace globe::dem {

// Whether a source at least as fine as this one (other than itself) covers the point.
using CoverageTest = std::function<bool(double longitudeDegrees, double latitudeDegrees)>;

// 3t² − 2t³ of t clamped to [0, 1]: the ease of the blend (and of the tiler's feather).
double smoothstep(double t);

// Returns how many samples changed. Water samples are left alone. The weight of the finer value
// goes smoothly (smoothstep) from 0 at the grid's outer edge to 1 at marginDegrees inside it.
uint64_t blendIntoCoarser(DemGrid& grid, const CoarserSources& coarser,
                          const CoverageTest& sameOrFinerCovers, double marginDegrees);

}  // namespace globe::dem
