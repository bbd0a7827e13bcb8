// The terrain height H of the paper's Intersecting Point in its tile: the vertex height on a
// vertex, the higher of the two neighbours on a row or column, the highest of four in a quad.
#pragma once

#include <algorithm>

#include "collision/grid_location.hpp"
#include "collision/terrain_array.hpp"
#include "terrain/tin_tile.hpp"

namespace globe::collision {

enum class HeightCase {
  None,         // no height read (no tile, invalid input)
  Vertex,       // on a vertex (within the grid epsilon), or on a pole row (its highest vertex)
  RowOrColumn,  // on a row or column line between two vertices: the higher of the two
  Quad,         // inside a quad: the highest of its four vertices
  TileMaximum,  // early-out: the block was not read; the height is the tile's maximum
  Triangle,     // a TIN tile: the highest vertex of the triangle under the point (or of the
                // edge or vertex it lies on)
};

struct TileHeight {
  double heightMeters = 0.0;
  HeightCase heightCase = HeightCase::None;
};

// H per the paper for a point (canonical longitude) contained in the tile; no-data counts as
// 0 m. On a row at +-90 deg (all its vertices are the pole) H is the highest vertex of that row.
// A tile without a readable block (hasReadableBlock) gives {0, None}. A TIN tile (the block's
// `tin`) reads its triangles (terrain/tin_tile.hpp): the paper's rule on the triangle under the
// point, found in O(1) through the tile's cell grid.
// Inline: every QOTCD query runs it, and the call with its result through memory cost as much
// as the reads.
inline TileHeight qotcdTileHeight(const ArrayTile& tile, double longitudeRadians,
                                  double latitudeRadians) {
  if (!hasReadableBlock(tile)) return {};
  const terrain::HeightBlock& block = *tile.block;
  if (block.tin) {
    const terrain::TinHeight t = block.tin->heightAt(longitudeRadians, latitudeRadians);
    if (t.found) return {t.conservativeMeters, HeightCase::Triangle};
    // No triangle there (a TIN that leaves part of its tile open): its sampled grid.
  }
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
