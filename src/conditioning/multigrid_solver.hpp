// Harmonic interpolation over a dense local grid by multigrid: V-cycles of Gauss-Seidel
// smoothing with 2×2 aggregation and the Galerkin coarse operator (still a weighted 5-point
// graph Laplacian), the coarse correction scaled to minimise the energy. Plain over-relaxation
// needs O(width) sweeps; this needs a few dozen cycles whatever the void's size.
#pragma once

#include <cstdint>
#include <vector>

namespace globe::conditioning {

enum class CellKind : uint8_t { Outside, Fixed, Unknown };

struct LocalGrid {
  int64_t rows = 0, cols = 0;
  std::vector<CellKind> kind;  // rows × cols
  std::vector<double> value;   // fixed values in, unknown values out
};

// Unknown cells become the harmonic interpolation of their fixed neighbours (5-point stencil;
// Outside neighbours are left out: zero slope there), until no unknown's residual (metres, as a
// Jacobi update) exceeds toleranceMeters.
void solveMultigrid(LocalGrid& grid, double toleranceMeters);

}  // namespace globe::conditioning
