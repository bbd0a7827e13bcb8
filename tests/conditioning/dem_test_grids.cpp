#include "dem_test_grids.hpp"

namespace globe::testing {

conditioning::DemGrid makeGrid(int64_t rows, int64_t cols,
                               const std::function<int16_t(int64_t, int64_t)>& f,
                               double stepDegrees, double lon0, double lat0) {
  conditioning::DemGrid grid;
  grid.rows = rows;
  grid.cols = cols;
  grid.firstColumnLongitudeDegrees = lon0;
  grid.firstRowLatitudeDegrees = lat0;
  grid.columnStepDegrees = grid.rowStepDegrees = stepDegrees;
  grid.samples.resize(static_cast<size_t>(rows * cols));
  for (int64_t r = 0; r < rows; ++r) {
    for (int64_t c = 0; c < cols; ++c) grid.samples[grid.index(r, c)] = f(r, c);
  }
  return grid;
}

}  // namespace globe::testing
