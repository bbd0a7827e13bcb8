#include "conditioning/multigrid_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace globe::conditioning {
namespace {

constexpr size_t kCoarsestUnknowns = 64;
constexpr int kMaxCycles = 200;
constexpr int kSmoothingSweeps = 2;

// One level: a weighted graph Laplacian on a rows × cols lattice. For unknown cell i,
// (A x)_i = diagonal_i x_i − Σ_j weight_ij x_j over its 4 lattice neighbours j.
struct Level {
  int64_t rows = 0, cols = 0;
  std::vector<uint8_t> unknown;
  std::vector<std::array<double, 4>> weight;  // to north, south, west, east
  std::vector<double> diagonal;
  size_t unknownCount = 0;

  std::array<int64_t, 4> neighbours(int64_t i) const {
    const int64_t r = i / cols, c = i % cols;
    return {r > 0 ? i - cols : -1, r + 1 < rows ? i + cols : -1, c > 0 ? i - 1 : -1,
            c + 1 < cols ? i + 1 : -1};
  }
  double offDiagonalProduct(const std::vector<double>& x, int64_t i) const {
    double sum = 0;
    const auto n = neighbours(i);
    for (size_t k = 0; k < 4; ++k) {
      if (n[k] >= 0 && unknown[static_cast<size_t>(n[k])])
        sum += weight[static_cast<size_t>(i)][k] * x[static_cast<size_t>(n[k])];
    }
    return sum;
  }
  void smooth(std::vector<double>& x, const std::vector<double>& b, int sweeps) const {
    for (int s = 0; s < sweeps; ++s) {
      for (int64_t i = 0; i < rows * cols; ++i) {
        const auto u = static_cast<size_t>(i);
        if (!unknown[u] || diagonal[u] <= 0) continue;
        x[u] = (b[u] + offDiagonalProduct(x, i)) / diagonal[u];
      }
    }
  }
  std::vector<double> residual(const std::vector<double>& x, const std::vector<double>& b) const {
    std::vector<double> r(x.size(), 0.0);
    for (int64_t i = 0; i < rows * cols; ++i) {
      const auto u = static_cast<size_t>(i);
      if (unknown[u]) r[u] = b[u] - (diagonal[u] * x[u] - offDiagonalProduct(x, i));
    }
    return r;
  }
};

// Galerkin coarsening by 2×2 aggregates: coarse weights count the fine edges between two
// aggregates' unknowns; the coarse diagonal keeps every fine edge leaving the aggregate.
Level coarsen(const Level& fine) {
  Level coarse;
  coarse.rows = (fine.rows + 1) / 2;
  coarse.cols = (fine.cols + 1) / 2;
  const auto cells = static_cast<size_t>(coarse.rows * coarse.cols);
  coarse.unknown.assign(cells, 0);
  coarse.weight.assign(cells, {0, 0, 0, 0});
  coarse.diagonal.assign(cells, 0.0);
  for (int64_t i = 0; i < fine.rows * fine.cols; ++i) {
    const auto u = static_cast<size_t>(i);
    if (!fine.unknown[u]) continue;
    const int64_t r = i / fine.cols, c = i % fine.cols;
    const int64_t I = (r / 2) * coarse.cols + c / 2;
    const auto U = static_cast<size_t>(I);
    coarse.unknown[U] = 1;
    double inside = 0;  // weights to unknowns of the same aggregate cancel
    const auto n = fine.neighbours(i);
    for (size_t k = 0; k < 4; ++k) {
      if (n[k] < 0 || !fine.unknown[static_cast<size_t>(n[k])]) continue;
      const int64_t J = (n[k] / fine.cols / 2) * coarse.cols + (n[k] % fine.cols) / 2;
      if (J == I) {
        inside += fine.weight[u][k];
      } else {
        coarse.weight[U][k] += fine.weight[u][k];  // direction k from I reaches J
      }
    }
    coarse.diagonal[U] += fine.diagonal[u] - inside;
  }
  coarse.unknownCount =
      static_cast<size_t>(std::count(coarse.unknown.begin(), coarse.unknown.end(), uint8_t{1}));
  return coarse;
}

struct Hierarchy {
  std::vector<Level> levels;
};

void vCycle(const Hierarchy& h, size_t depth, std::vector<double>& x,
            const std::vector<double>& b) {
  const Level& level = h.levels[depth];
  if (depth + 1 == h.levels.size()) {
    level.smooth(x, b, 50 + 4 * static_cast<int>(std::max(level.rows, level.cols)));
    return;
  }
  level.smooth(x, b, kSmoothingSweeps);
  const std::vector<double> r = level.residual(x, b);
  const Level& coarse = h.levels[depth + 1];
  std::vector<double> bc(static_cast<size_t>(coarse.rows * coarse.cols), 0.0);
  for (int64_t i = 0; i < level.rows * level.cols; ++i) {
    if (!level.unknown[static_cast<size_t>(i)]) continue;
    bc[static_cast<size_t>((i / level.cols / 2) * coarse.cols + (i % level.cols) / 2)] +=
        r[static_cast<size_t>(i)];
  }
  std::vector<double> xc(bc.size(), 0.0);
  vCycle(h, depth + 1, xc, bc);
  // Prolong (constant over each aggregate), scaled to minimise the energy along it.
  std::vector<double> p(x.size(), 0.0);
  for (int64_t i = 0; i < level.rows * level.cols; ++i) {
    if (level.unknown[static_cast<size_t>(i)]) {
      p[static_cast<size_t>(i)] =
          xc[static_cast<size_t>((i / level.cols / 2) * coarse.cols + (i % level.cols) / 2)];
    }
  }
  double pr = 0, pAp = 0;
  for (int64_t i = 0; i < level.rows * level.cols; ++i) {
    const auto u = static_cast<size_t>(i);
    if (!level.unknown[u]) continue;
    pr += p[u] * r[u];
    pAp += p[u] * (level.diagonal[u] * p[u] - level.offDiagonalProduct(p, i));
  }
  const double alpha = pAp > 0 ? pr / pAp : 1.0;
  for (size_t u = 0; u < x.size(); ++u) x[u] += alpha * p[u];
  level.smooth(x, b, kSmoothingSweeps);
}

}  // namespace

void solveMultigrid(LocalGrid& grid, double toleranceMeters) {
  Hierarchy h;
  Level finest;
  finest.rows = grid.rows;
  finest.cols = grid.cols;
  const auto cells = static_cast<size_t>(grid.rows * grid.cols);
  finest.unknown.assign(cells, 0);
  finest.weight.assign(cells, {0, 0, 0, 0});
  finest.diagonal.assign(cells, 0.0);
  std::vector<double> b(cells, 0.0), x(cells, 0.0);
  double fixedSum = 0;
  size_t fixedCount = 0;
  for (int64_t i = 0; i < grid.rows * grid.cols; ++i) {
    const auto u = static_cast<size_t>(i);
    if (grid.kind[u] == CellKind::Fixed) fixedSum += grid.value[u], ++fixedCount;
    if (grid.kind[u] != CellKind::Unknown) continue;
    finest.unknown[u] = 1;
    ++finest.unknownCount;
    const auto n = finest.neighbours(i);
    for (size_t k = 0; k < 4; ++k) {
      if (n[k] < 0) continue;
      const auto v = static_cast<size_t>(n[k]);
      if (grid.kind[v] == CellKind::Outside) continue;
      finest.diagonal[u] += 1.0;
      if (grid.kind[v] == CellKind::Fixed) {
        b[u] += grid.value[v];
      } else {
        finest.weight[u][k] = 1.0;
      }
    }
  }
  // Start from the border's mean (within its range, so the max principle is kept throughout).
  const double mean = fixedCount > 0 ? fixedSum / static_cast<double>(fixedCount) : 0.0;
  for (size_t u = 0; u < cells; ++u) {
    if (finest.unknown[u]) x[u] = mean;
  }
  h.levels.push_back(std::move(finest));
  while (h.levels.back().unknownCount > kCoarsestUnknowns && h.levels.back().rows > 2 &&
         h.levels.back().cols > 2) {
    h.levels.push_back(coarsen(h.levels.back()));
  }
  const Level& top = h.levels.front();
  for (int cycle = 0; cycle < kMaxCycles; ++cycle) {
    vCycle(h, 0, x, b);
    const std::vector<double> r = top.residual(x, b);
    double worst = 0;
    for (size_t u = 0; u < cells; ++u) {
      if (top.unknown[u] && top.diagonal[u] > 0)
        worst = std::max(worst, std::abs(r[u]) / top.diagonal[u]);
    }
    if (worst < toleranceMeters) break;
  }
  for (size_t u = 0; u < cells; ++u) {
    if (grid.kind[u] == CellKind::Unknown) grid.value[u] = x[u];
  }
}

}  // namespace globe::conditioning
