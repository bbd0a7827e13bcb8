// Where the vertices of a tile's block lie: vertex (i, j) of tile (L, x, y) is at
// longitude west + j·width/(N−1), latitude north − i·height/(N−1), computed exactly in degrees.
#pragma once

#include <cstdint>

#include "geo/tile_id.hpp"

namespace globe::terrain {

// Degrees between neighbouring vertices at a level: 180 / (2^level · (N−1)), a dyadic number, so
// every vertex position below is exact in double and shared vertices of neighbours are identical.
double vertexSpacingDegrees(uint32_t level, uint32_t verticesPerSide);

// Global vertex indices at a level: column 0 is −180°, row 0 is +90°.
double vertexLongitudeDegrees(uint32_t level, uint32_t verticesPerSide, uint64_t globalColumn);
double vertexLatitudeDegrees(uint32_t level, uint32_t verticesPerSide, uint64_t globalRow);

struct BlockGrid {
  geo::TileId tile;
  uint32_t verticesPerSide;

  uint64_t globalColumn(uint32_t column) const {
    return uint64_t{tile.x} * (verticesPerSide - 1) + column;
  }
  uint64_t globalRow(uint32_t row) const { return uint64_t{tile.y} * (verticesPerSide - 1) + row; }
  double longitudeDegrees(uint32_t column) const {
    return vertexLongitudeDegrees(tile.level, verticesPerSide, globalColumn(column));
  }
  double latitudeDegrees(uint32_t row) const {
    return vertexLatitudeDegrees(tile.level, verticesPerSide, globalRow(row));
  }

  // The level's vertex at (row, column) relative to this tile, for row and column in [-1, N]
  // (the apron ring included): longitudes wrap across ±180°; a row beyond a pole is the vertex
  // mirrored over the pole (the same distance from it, on the opposite meridian), so it is the
  // real ground neighbour of the edge vertex. Identical, bit for bit, to what the tile that holds
  // that vertex computes for it.
  struct Vertex {
    double longitudeDegrees;
    double latitudeDegrees;
  };
  Vertex wrappedVertex(int row, int column) const;
};

}  // namespace globe::terrain
