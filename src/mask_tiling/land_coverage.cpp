#include "mask_tiling/land_coverage.hpp"

#include <algorithm>
#include <cmath>

namespace globe::mask_tiling {

void countLandPoints(const std::vector<Ring>& rings, const TexelGrid& grid, int supersample,
                     std::vector<uint16_t>& counts) {
  const int points = grid.size * supersample;  // supersample points per side
  const double spacing = grid.stepDegrees / supersample;
  // Point (k, j) at longitude x0 + j·spacing, latitude y0 − k·spacing: the centres of the
  // supersample cells of each sample's box.
  const double x0 = grid.westDegrees - grid.stepDegrees / 2 + spacing / 2;
  const double y0 = grid.northDegrees + grid.stepDegrees / 2 - spacing / 2;
  counts.assign(static_cast<size_t>(grid.size) * grid.size, 0);
  // Every edge's crossings of each point row (a row at y crosses an edge when y is in
  // [min y, max y): a vertex on the row is counted once, a horizontal edge never).
  std::vector<std::vector<double>> crossings(static_cast<size_t>(points));
  for (const Ring& ring : rings) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const glm::dvec2& a = ring[i];
      const glm::dvec2& b = ring[(i + 1) % ring.size()];
      if (a.y == b.y) continue;
      const double low = std::min(a.y, b.y), high = std::max(a.y, b.y);
      // Row k is at y0 − k·spacing: y < high ⇔ k > (y0 − high) / spacing.
      const double kAbove = (y0 - high) / spacing, kBelow = (y0 - low) / spacing;
      int first = static_cast<int>(std::floor(kAbove)) + 1;
      int last = static_cast<int>(std::floor(kBelow));
      first = std::max(first, 0);
      last = std::min(last, points - 1);
      const double slope = (b.x - a.x) / (b.y - a.y);
      for (int k = first; k <= last; ++k) {
        const double y = y0 - k * spacing;
        if (y < low || y >= high) continue;  // rounding at the ends
        crossings[static_cast<size_t>(k)].push_back(a.x + (y - a.y) * slope);
      }
    }
  }
  for (int k = 0; k < points; ++k) {
    std::vector<double>& row = crossings[static_cast<size_t>(k)];
    if (row.empty()) continue;
    std::sort(row.begin(), row.end());
    uint16_t* out = &counts[static_cast<size_t>(k / supersample) * grid.size];
    // Points j with x in (row[i], row[i+1]] are inside: j from ⌊u⌋+1 to ⌊v⌋, u and v the
    // crossings in point units.
    for (size_t i = 0; i + 1 < row.size(); i += 2) {
      const double u = (row[i] - x0) / spacing, v = (row[i + 1] - x0) / spacing;
      const int first = std::max(static_cast<int>(std::floor(std::max(u, -1.0))) + 1, 0);
      const int last =
          std::min(static_cast<int>(std::floor(std::min(v, double(points)))), points - 1);
      for (int j = first; j <= last; ++j) ++out[j / supersample];
    }
  }
}

}  // namespace globe::mask_tiling
