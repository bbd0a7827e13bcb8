#include "terrain/block_grid.hpp"

#include <cmath>
#include <cstdint>

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

BlockGrid::Vertex BlockGrid::wrappedVertex(int row, int column) const {
  const auto cells = static_cast<int64_t>(verticesPerSide - 1);
  const int64_t columns = int64_t{2} * cells << tile.level;  // around the globe
  const int64_t rows = cells << tile.level;                  // pole to pole
  int64_t globalRowIndex = int64_t{tile.y} * cells + row;
  int64_t globalColumnIndex = int64_t{tile.x} * cells + column;
  if (globalRowIndex < 0 || globalRowIndex > rows) {
    globalRowIndex = globalRowIndex < 0 ? -globalRowIndex : 2 * rows - globalRowIndex;
    globalColumnIndex += columns / 2;
  }
  globalColumnIndex = ((globalColumnIndex % columns) + columns) % columns;
  return {
      vertexLongitudeDegrees(tile.level, verticesPerSide, static_cast<uint64_t>(globalColumnIndex)),
      vertexLatitudeDegrees(tile.level, verticesPerSide, static_cast<uint64_t>(globalRowIndex))};
}

}  // namespace globe::terrain
