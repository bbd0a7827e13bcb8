#include "conditioning/minimum_curvature.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace globe::conditioning {
namespace {

constexpr int kMaxIterations = 4000;
constexpr double kRelativeTolerance = 1e-7;

enum class Kind : uint8_t { Outside, Fixed, Unknown };

}  // namespace

std::vector<double> solveMinimumCurvature(
    const DemGrid& grid, const std::vector<uint8_t>& isVoid, const std::vector<size_t>& region,
    const std::function<double(int64_t, int64_t)>& borderValue, std::vector<double> start,
    double tension) {
  const auto cols = static_cast<size_t>(grid.cols);
  int64_t minRow = grid.rows, maxRow = -1, minColumn = grid.cols, maxColumn = -1;
  for (size_t i : region) {
    const auto r = static_cast<int64_t>(i / cols), c = static_cast<int64_t>(i % cols);
    minRow = std::min(minRow, r), maxRow = std::max(maxRow, r);
    minColumn = std::min(minColumn, c), maxColumn = std::max(maxColumn, c);
  }
  // The void and two rings around it, within the grid (no wrapping: a seam-crossing void keeps
  // its harmonic fill).
  if (grid.wrapsLongitude && (minColumn == 0 || maxColumn == grid.cols - 1)) return start;
  const int64_t row0 = std::max<int64_t>(minRow - 2, 0),
                column0 = std::max<int64_t>(minColumn - 2, 0);
  const int64_t rows = std::min(maxRow + 2, grid.rows - 1) - row0 + 1;
  const int64_t localCols = std::min(maxColumn + 2, grid.cols - 1) - column0 + 1;
  const auto cells = static_cast<size_t>(rows * localCols);
  std::vector<Kind> kind(cells, Kind::Outside);
  std::vector<double> value(cells, 0.0);
  std::vector<int32_t> unknownOf(cells, -1);
  auto local = [&](int64_t r, int64_t c) {
    return static_cast<size_t>((r - row0) * localCols + (c - column0));
  };
  for (size_t k = 0; k < region.size(); ++k) {
    const size_t l =
        local(static_cast<int64_t>(region[k] / cols), static_cast<int64_t>(region[k] % cols));
    kind[l] = Kind::Unknown;
    unknownOf[l] = static_cast<int32_t>(k);
    value[l] = start[k];
  }
  double borderLow = 1e300, borderHigh = -1e300;
  for (int64_t r = row0; r < row0 + rows; ++r) {
    for (int64_t c = column0; c < column0 + localCols; ++c) {
      const size_t l = local(r, c);
      if (kind[l] == Kind::Unknown || isVoid[grid.index(r, c)] != 0) continue;
      kind[l] = Kind::Fixed;
      value[l] = borderValue(r, c);
    }
  }
  // The border's range: the 4-neighbours of the void.
  for (size_t i : region) {
    const auto r = static_cast<int64_t>(i / cols), c = static_cast<int64_t>(i % cols);
    for (auto [rr, cc] : {std::pair{r - 1, c}, {r + 1, c}, {r, c - 1}, {r, c + 1}}) {
      if (rr < row0 || rr >= row0 + rows || cc < column0 || cc >= column0 + localCols) continue;
      if (kind[local(rr, cc)] == Kind::Fixed) {
        borderLow = std::min(borderLow, value[local(rr, cc)]);
        borderHigh = std::max(borderHigh, value[local(rr, cc)]);
      }
    }
  }
  if (borderLow > borderHigh) return start;

  // Equations: the 5-point Laplacian at every cell whose stencil is all known or unknown and
  // touches an unknown. A x + b, with b the fixed cells' part.
  struct Equation {
    std::array<int32_t, 5> unknown;  // centre, N, S, W, E (-1: fixed)
    double fixedPart;
  };
  std::vector<Equation> equations;
  for (int64_t r = row0 + 1; r + 1 < row0 + rows; ++r) {
    for (int64_t c = column0 + 1; c + 1 < column0 + localCols; ++c) {
      const std::array<size_t, 5> at = {local(r, c), local(r - 1, c), local(r + 1, c),
                                        local(r, c - 1), local(r, c + 1)};
      bool complete = true, touches = false;
      for (size_t l : at) {
        complete = complete && kind[l] != Kind::Outside;
        touches = touches || kind[l] == Kind::Unknown;
      }
      if (!complete || !touches) continue;
      Equation e{{-1, -1, -1, -1, -1}, 0.0};
      for (size_t k = 0; k < 5; ++k) {
        const double weight = k == 0 ? -4.0 : 1.0;
        if (kind[at[k]] == Kind::Unknown) {
          e.unknown[k] = unknownOf[at[k]];
        } else {
          e.fixedPart += weight * value[at[k]];
        }
      }
      equations.push_back(e);
    }
  }
  // Tension (Smith & Wessel): the gradient's squares too, weighted T against the curvature's
  // 1 - T, so large voids do not bulge. Each edge touching an unknown: x_a - x_b.
  const double curvatureWeight = std::sqrt(1.0 - tension), gradientWeight = std::sqrt(tension);
  for (Equation& e : equations) e.fixedPart *= curvatureWeight;
  const size_t curvatureEquations = equations.size();
  struct Edge {
    int32_t a, b;
    double fixedPart;
  };
  std::vector<Edge> edges;
  if (tension > 0) {
    for (int64_t r = row0; r < row0 + rows; ++r) {
      for (int64_t c = column0; c < column0 + localCols; ++c) {
        const size_t l = local(r, c);
        if (kind[l] == Kind::Outside) continue;
        for (auto [rr, cc] : {std::pair{r + 1, c}, {r, c + 1}}) {
          if (rr >= row0 + rows || cc >= column0 + localCols) continue;
          const size_t m = local(rr, cc);
          if (kind[m] == Kind::Outside) continue;
          if (kind[l] != Kind::Unknown && kind[m] != Kind::Unknown) continue;
          Edge e{unknownOf[l], unknownOf[m], 0.0};
          if (kind[l] != Kind::Unknown) e.fixedPart += gradientWeight * value[l];
          if (kind[m] != Kind::Unknown) e.fixedPart -= gradientWeight * value[m];
          edges.push_back(e);
        }
      }
    }
  }
  auto weightOf = [&](size_t k) { return curvatureWeight * (k == 0 ? -4.0 : 1.0); };
  auto applyA = [&](const std::vector<double>& x, std::vector<double>& out) {
    for (size_t q = 0; q < equations.size(); ++q) {
      double sum = 0;
      for (size_t k = 0; k < 5; ++k) {
        if (equations[q].unknown[k] >= 0)
          sum += weightOf(k) * x[static_cast<size_t>(equations[q].unknown[k])];
      }
      out[q] = sum;
    }
    for (size_t k = 0; k < edges.size(); ++k) {
      double sum = 0;
      if (edges[k].a >= 0) sum += gradientWeight * x[static_cast<size_t>(edges[k].a)];
      if (edges[k].b >= 0) sum -= gradientWeight * x[static_cast<size_t>(edges[k].b)];
      out[curvatureEquations + k] = sum;
    }
  };
  auto applyAt = [&](const std::vector<double>& y, std::vector<double>& out) {
    std::fill(out.begin(), out.end(), 0.0);
    for (size_t q = 0; q < equations.size(); ++q) {
      for (size_t k = 0; k < 5; ++k) {
        if (equations[q].unknown[k] >= 0)
          out[static_cast<size_t>(equations[q].unknown[k])] += weightOf(k) * y[q];
      }
    }
    for (size_t k = 0; k < edges.size(); ++k) {
      const double yk = y[curvatureEquations + k];
      if (edges[k].a >= 0) out[static_cast<size_t>(edges[k].a)] += gradientWeight * yk;
      if (edges[k].b >= 0) out[static_cast<size_t>(edges[k].b)] -= gradientWeight * yk;
    }
  };
  auto dot = [](const std::vector<double>& a, const std::vector<double>& b) {
    double sum = 0;
    for (size_t i = 0; i < a.size(); ++i) sum += a[i] * b[i];
    return sum;
  };

  // CGLS: minimise |A x + b|² from x = start.
  const size_t rowsTotal = equations.size() + edges.size();
  std::vector<double> x = start, residual(rowsTotal), q(rowsTotal), s(x.size()), p(x.size());
  applyA(x, residual);
  for (size_t i = 0; i < equations.size(); ++i)
    residual[i] = -(residual[i] + equations[i].fixedPart);
  for (size_t k = 0; k < edges.size(); ++k) {
    residual[curvatureEquations + k] = -(residual[curvatureEquations + k] + edges[k].fixedPart);
  }
  applyAt(residual, s);
  p = s;
  double gamma = dot(s, s);
  const double gamma0 = gamma;
  for (int iteration = 0; iteration < kMaxIterations &&
                          gamma > kRelativeTolerance * kRelativeTolerance * gamma0 && gamma > 0;
       ++iteration) {
    applyA(p, q);
    const double qq = dot(q, q);
    if (!(qq > 0)) break;
    const double alpha = gamma / qq;
    for (size_t i = 0; i < x.size(); ++i) x[i] += alpha * p[i];
    for (size_t i = 0; i < q.size(); ++i) residual[i] -= alpha * q[i];
    applyAt(residual, s);
    const double next = dot(s, s);
    const double beta = next / gamma;
    gamma = next;
    for (size_t i = 0; i < p.size(); ++i) p[i] = s[i] + beta * p[i];
  }
  for (double& v : x) v = std::clamp(v, borderLow, borderHigh);
  return x;
}

}  // namespace globe::conditioning
