// The smoothest surface over a void: the discrete harmonic function (5-point Laplacian) equal to
// given values on the void's border, found by successive over-relaxation from a peeled guess.
// A harmonic fill never leaves its border's range (maximum principle).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "conditioning/dem_grid.hpp"

namespace globe::conditioning {

// Calls f(row, column) for each 4-neighbour in the grid (columns wrap on wrapping grids).
template <typename F>
void forEachNeighbour(const DemGrid& grid, int64_t row, int64_t column, F&& f) {
  if (row > 0) f(row - 1, column);
  if (row + 1 < grid.rows) f(row + 1, column);
  if (column > 0) {
    f(row, column - 1);
  } else if (grid.wrapsLongitude && grid.cols > 2) {
    f(row, grid.cols - 1);
  }
  if (column + 1 < grid.cols) {
    f(row, column + 1);
  } else if (grid.wrapsLongitude && grid.cols > 2) {
    f(row, 0);
  }
}

// region: the sorted sample indices of one 4-connected void (isVoid set on all of them, and on
// no 4-neighbour outside it). borderValue(row, column) gives the fixed value of a non-void
// neighbour. Returns the value at each region sample (region order); nullopt when the region
// has no non-void neighbour. Neighbours beyond the grid's edge are left out (zero slope there).
// toleranceMeters: the largest change one more relaxation would make (a fill wants a
// millimetre; a bend of whole metres, less). thinExtentSamples > 0: a region that fills less than
// a quarter of its bounding box (a collar of no data round a large raster) is relaxed on its own
// samples, its over-relaxation tuned for that many samples across, instead of densely over the
// whole box (whose memory and time grow with the raster, not the region).
std::optional<std::vector<double>> solveHarmonic(
    const DemGrid& grid, const std::vector<uint8_t>& isVoid, const std::vector<size_t>& region,
    const std::function<double(int64_t, int64_t)>& borderValue, double toleranceMeters = 1e-3,
    double thinExtentSamples = 0);

}  // namespace globe::conditioning
