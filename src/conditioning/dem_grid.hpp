// A source's elevation samples in memory on its geographic grid (geo::SampleGrid: sample centres,
// rows from the north), in the block encoding of terrain/height_block.hpp: -9999 = no data before
// conditioning, water after it.
#pragma once

#include <cstdint>
#include <vector>

#include "geo/sample_grid.hpp"

namespace globe::conditioning {

struct DemGrid : geo::SampleGrid {
  std::vector<int16_t> samples;  // row-major, rows × cols

  int16_t at(int64_t row, int64_t column) const { return samples[index(row, column)]; }
};

}  // namespace globe::conditioning
