// Small synthetic grids for the dem tests: a 1/100° grid near (10°E, 45°N) by default.
#pragma once

#include <functional>

#include "conditioning/dem_grid.hpp"

namespace globe::testing {

// rows × cols samples from f(row, column), sample (0, 0) at (lon0, lat0), step in degrees.
conditioning::DemGrid makeGrid(int64_t rows, int64_t cols,
                               const std::function<int16_t(int64_t, int64_t)>& f,
                               double stepDegrees = 0.01, double lon0 = 10.0, double lat0 = 45.0);

}  // namespace globe::testing
