#include "terrain/block_grid.hpp"

#include <cmath>

namespace globe::terrain {

double vertexSpacingDegrees(uint32_t level, uint32_t verticesPerSide) {
  return std::ldexp(180.0 / (verticesPerSide - 1), -static_cast<int>(level));
}

double vertexLongitudeDegrees(uint32_t level, uint32_t verticesPerSide, uint64_t globalColumn) {
  return -180.0 + static_cast<double>(globalColumn) * vertexSpacingDegrees(level, verticesPerSide);
}

double vertexLatitudeDegrees(uint32_t level, uint32_t verticesPerSide, uint64_t globalRow) {
  return 90.0 - static_cast<double>(globalRow) * vertexSpacingDegrees(level, verticesPerSide);
}

}  // namespace globe::terrain
