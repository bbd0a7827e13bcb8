#include "conditioning/harmonic_fill.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "conditioning/multigrid_solver.hpp"

namespace globe::conditioning {
namespace {

constexpr size_t kDenseMinimumSamples = 1024;

struct Unknown {
  std::array<int32_t, 4> neighbours{-1, -1, -1, -1};  // other unknowns
  double fixedSum = 0;                                // of the border neighbours' values
  uint8_t count = 0;                                  // neighbours of either kind
};

// The void and its border ring as a dense local grid, solved by multigrid.
std::vector<double> solveDense(const DemGrid& grid, const std::vector<uint8_t>& isVoid,
                               const std::vector<size_t>& region,
                               const std::function<double(int64_t, int64_t)>& borderValue,
                               int64_t minRow, int64_t maxRow, int64_t minColumn, int64_t maxColumn,
                               double toleranceMeters) {
  const int64_t row0 = std::max<int64_t>(minRow - 1, 0);
  const int64_t column0 = std::max<int64_t>(minColumn - 1, 0);
  LocalGrid local;
  local.rows = std::min(maxRow + 1, grid.rows - 1) - row0 + 1;
  local.cols = std::min(maxColumn + 1, grid.cols - 1) - column0 + 1;
  const auto cells = static_cast<size_t>(local.rows * local.cols);
  local.kind.assign(cells, CellKind::Outside);
  local.value.assign(cells, 0.0);
  auto localIndex = [&](int64_t r, int64_t c) {
    return static_cast<size_t>((r - row0) * local.cols + (c - column0));
  };
  const auto cols = static_cast<size_t>(grid.cols);
  for (size_t i : region) {
    const auto row = static_cast<int64_t>(i / cols), column = static_cast<int64_t>(i % cols);
    local.kind[localIndex(row, column)] = CellKind::Unknown;
  }
  for (size_t i : region) {
    const auto row = static_cast<int64_t>(i / cols), column = static_cast<int64_t>(i % cols);
    for (auto [r, c] :
         {std::pair{row - 1, column}, {row + 1, column}, {row, column - 1}, {row, column + 1}}) {
      if (r < 0 || r >= grid.rows || c < 0 || c >= grid.cols) continue;
      const size_t k = localIndex(r, c);
      if (isVoid[grid.index(r, c)] == 0 && local.kind[k] == CellKind::Outside) {
        local.kind[k] = CellKind::Fixed;
        local.value[k] = borderValue(r, c);
      }
    }
  }
  solveMultigrid(local, toleranceMeters / 10);
  std::vector<double> values(region.size());
  for (size_t k = 0; k < region.size(); ++k) {
    values[k] = local.value[localIndex(static_cast<int64_t>(region[k] / cols),
                                       static_cast<int64_t>(region[k] % cols))];
  }
  return values;
}

}  // namespace

std::optional<std::vector<double>> solveHarmonic(
    const DemGrid& grid, const std::vector<uint8_t>& isVoid, const std::vector<size_t>& region,
    const std::function<double(int64_t, int64_t)>& borderValue, double toleranceMeters,
    double thinExtentSamples) {
  const auto cols = static_cast<size_t>(grid.cols);
  bool anyBorder = false;
  int64_t minRow = grid.rows, maxRow = -1, minColumn = grid.cols, maxColumn = -1;
  for (size_t i : region) {
    const auto row = static_cast<int64_t>(i / cols), column = static_cast<int64_t>(i % cols);
    minRow = std::min(minRow, row), maxRow = std::max(maxRow, row);
    minColumn = std::min(minColumn, column), maxColumn = std::max(maxColumn, column);
    forEachNeighbour(grid, row, column, [&](int64_t r, int64_t c) {
      anyBorder = anyBorder || isVoid[grid.index(r, c)] == 0;
    });
  }
  if (!anyBorder) return std::nullopt;

  // Large voids: solved densely over their bounding box by multigrid (a void across the
  // antimeridian of a wrapping grid keeps the sparse path below).
  const bool crossesSeam = grid.wrapsLongitude && (minColumn == 0 || maxColumn == grid.cols - 1);
  const double boxSamples =
      static_cast<double>(maxRow - minRow + 1) * static_cast<double>(maxColumn - minColumn + 1);
  const bool thin = thinExtentSamples > 0 && static_cast<double>(region.size()) * 4 < boxSamples;
  if (region.size() > kDenseMinimumSamples && !crossesSeam && !thin) {
    return solveDense(grid, isVoid, region, borderValue, minRow, maxRow, minColumn, maxColumn,
                      toleranceMeters);
  }

  // Small voids: the unknowns' neighbour graph, relaxed in place.
  std::vector<Unknown> unknowns(region.size());
  for (size_t k = 0; k < region.size(); ++k) {
    Unknown& u = unknowns[k];
    uint8_t inner = 0;
    forEachNeighbour(grid, static_cast<int64_t>(region[k] / cols),
                     static_cast<int64_t>(region[k] % cols), [&](int64_t r, int64_t c) {
                       const size_t i = grid.index(r, c);
                       ++u.count;
                       if (isVoid[i] != 0) {
                         const auto at = std::lower_bound(region.begin(), region.end(), i);
                         u.neighbours[inner++] = static_cast<int32_t>(at - region.begin());
                       } else {
                         u.fixedSum += borderValue(r, c);
                       }
                     });
  }

  // Initial guess: peel the void from its border inwards, each sample the mean of the neighbours
  // already known (a good start, so few relaxation sweeps are needed).
  std::vector<double> values(region.size(), 0.0);
  std::vector<uint8_t> known(region.size(), 0);
  std::vector<size_t> front;
  for (size_t k = 0; k < region.size(); ++k) {
    if (unknowns[k].count > std::count_if(unknowns[k].neighbours.begin(),
                                          unknowns[k].neighbours.end(),
                                          [](int32_t n) { return n >= 0; })) {
      front.push_back(k);
    }
  }
  while (!front.empty()) {
    for (size_t k : front) {
      const Unknown& u = unknowns[k];
      double sum = u.fixedSum;
      int fixed = u.count;
      int used = 0;
      for (int32_t n : u.neighbours) {
        if (n < 0) continue;
        --fixed;
        if (known[static_cast<size_t>(n)] != 0) sum += values[static_cast<size_t>(n)], ++used;
      }
      values[k] = sum / (fixed + used);
    }
    for (size_t k : front) known[k] = 1;
    std::vector<size_t> next;
    for (size_t k : front) {
      for (int32_t n : unknowns[k].neighbours) {
        if (n >= 0 && known[static_cast<size_t>(n)] == 0) {
          known[static_cast<size_t>(n)] = 2;  // queued
          next.push_back(static_cast<size_t>(n));
        }
      }
    }
    std::sort(next.begin(), next.end());
    for (size_t k : next) known[k] = 0;
    front = std::move(next);
  }

  // Successive over-relaxation with the optimal factor for a square of the void's extent (or of
  // a thin region's width).
  const double extent =
      thin ? thinExtentSamples + 2
           : static_cast<double>(std::max(maxRow - minRow, maxColumn - minColumn) + 2);
  const double omega = 2.0 / (1.0 + std::sin(std::numbers::pi / extent));
  const int maxSweeps = static_cast<int>(std::min(100000.0, 20.0 * extent + 200.0));
  for (int sweep = 0; sweep < maxSweeps; ++sweep) {
    double largestChange = 0;
    for (size_t k = 0; k < region.size(); ++k) {
      const Unknown& u = unknowns[k];
      double sum = u.fixedSum;
      for (int32_t n : u.neighbours) {
        if (n >= 0) sum += values[static_cast<size_t>(n)];
      }
      const double change = omega * (sum / u.count - values[k]);
      values[k] += change;
      largestChange = std::max(largestChange, std::abs(change));
    }
    if (largestChange < toleranceMeters) break;
  }
  return values;
}

}  // namespace globe::conditioning
