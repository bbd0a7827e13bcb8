// Reading the paper's H from a tile's block: vertex, row/column and quad cases.
#include "collision/qotcd_height.hpp"

#include <algorithm>

#include "collision/grid_location.hpp"

namespace globe::collision {

TileHeight qotcdTileHeight(const ArrayTile& tile, double longitudeRadians, double latitudeRadians) {
  if (!hasReadableBlock(tile)) return {};
  const terrain::HeightBlock& block = *tile.block;
  const GridLocation at = locateInGrid(tile, longitudeRadians, latitudeRadians);
  auto h = [&block](uint32_t row, uint32_t column) {
    return block.surfaceHeightMetersAt(row, column);
  };
  if (at.atPole) {
    double highest = h(at.poleRow, 0);
    for (uint32_t column = 1; column < block.verticesPerSide; ++column) {
      highest = std::max(highest, h(at.poleRow, column));
    }
    return {highest, HeightCase::Vertex};
  }
  const uint32_t row = at.quadRow;
  const uint32_t column = at.quadColumn;
  if (at.onRow && at.onColumn) return {h(at.snappedRow, at.snappedColumn), HeightCase::Vertex};
  if (at.onColumn) {
    return {std::max(h(row, at.snappedColumn), h(row + 1, at.snappedColumn)),
            HeightCase::RowOrColumn};
  }
  if (at.onRow) {
    return {std::max(h(at.snappedRow, column), h(at.snappedRow, column + 1)),
            HeightCase::RowOrColumn};
  }
  return {
      std::max({h(row, column), h(row, column + 1), h(row + 1, column), h(row + 1, column + 1)}),
      HeightCase::Quad};
}

}  // namespace globe::collision
