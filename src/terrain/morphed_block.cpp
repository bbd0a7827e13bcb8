#include "terrain/morphed_block.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace globe::terrain {

HeightBlock morphBlock(const HeightBlock& from, const HeightBlock& to, double fraction) {
  const double f = std::isnan(fraction) ? 1.0 : std::clamp(fraction, 0.0, 1.0);
  HeightBlock block;
  block.verticesPerSide = to.verticesPerSide;
  block.heights = to.heights;
  block.sea = to.sea;
  block.apron = to.apron;
  const uint32_t n = to.verticesPerSide;
  if (from.verticesPerSide != n || from.heights.size() != to.heights.size()) {
    block.exactSurfaceMeters = to.exactSurfaceMeters;
    block.exactApronSurfaceMeters = to.exactApronSurfaceMeters;
    return block;
  }
  block.exactSurfaceMeters.resize(to.heights.size());
  for (uint32_t row = 0; row < n; ++row) {
    for (uint32_t column = 0; column < n; ++column) {
      const double a = from.surfaceHeightMetersAt(row, column);
      const double b = to.surfaceHeightMetersAt(row, column);
      block.exactSurfaceMeters[static_cast<size_t>(row) * n + column] = a + f * (b - a);
    }
  }
  if (!from.hasApron() || !to.hasApron()) {
    block.exactApronSurfaceMeters = to.exactApronSurfaceMeters;
    return block;
  }
  block.exactApronSurfaceMeters.resize(to.apron.size());
  const int w = kApronWidth, last = static_cast<int>(n) + w - 1;
  for (int row = -w; row <= last; ++row) {
    for (int column = -w; column <= last; ++column) {
      const bool inside = row >= 0 && row < static_cast<int>(n) && column >= 0 &&
                          column < static_cast<int>(n);
      if (inside) continue;
      const double a = from.surfaceHeightMetersWithApron(row, column);
      const double b = to.surfaceHeightMetersWithApron(row, column);
      block.exactApronSurfaceMeters[apronIndex(row, column, n)] = a + f * (b - a);
    }
  }
  return block;
}

}  // namespace globe::terrain
