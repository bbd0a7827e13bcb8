// A source's elevation samples in memory on its geographic grid (sample centres, rows from the
// north), in the block encoding of terrain/height_block.hpp: -9999 = no data before conditioning,
// water after it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace globe::conditioning {

struct DemGrid {
  int64_t cols = 0, rows = 0;
  double firstColumnLongitudeDegrees = 0;  // centre of column 0
  double firstRowLatitudeDegrees = 0;      // centre of row 0 (northernmost)
  double columnStepDegrees = 0;            // > 0, eastwards
  double rowStepDegrees = 0;               // > 0, southwards
  bool wrapsLongitude = false;             // the columns go once round the globe
  std::vector<int16_t> samples;            // row-major, rows × cols

  size_t index(int64_t row, int64_t column) const {
    return static_cast<size_t>(row) * static_cast<size_t>(cols) + static_cast<size_t>(column);
  }
  int16_t at(int64_t row, int64_t column) const { return samples[index(row, column)]; }
  double longitudeDegrees(int64_t column) const {
    return firstColumnLongitudeDegrees + static_cast<double>(column) * columnStepDegrees;
  }
  double latitudeDegrees(int64_t row) const {
    return firstRowLatitudeDegrees - static_cast<double>(row) * rowStepDegrees;
  }
};

}  // namespace globe::conditioning
