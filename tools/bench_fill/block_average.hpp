// A coarser grid made by averaging a fine one: how SRTM30 (30″) is derived from SRTM3 (3″).
#pragma once

#include <cstdint>

#include "conditioning/dem_grid.hpp"

namespace globe::bench_fill {

// Cells of `factor` × `factor` fine steps whose corners sit on fine samples (an SRTM tile's
// whole-degree lines): cell (r, c) spans fine rows and columns factor·r .. factor·(r+1) and is
// the area mean of the fine surface over it (the trapezoid rule: edge samples weigh 1/2,
// corners 1/4), rounded to whole metres. No-data fine samples are left out of the mean; a cell
// with none valid is no-data. The result has (fine.rows - 1) / factor rows, likewise columns.
conditioning::DemGrid blockAverage(const conditioning::DemGrid& fine, int64_t factor);

}  // namespace globe::bench_fill
