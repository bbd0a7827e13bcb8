// A terrain block: N×N vertex heights of one tile, in GTOPO30 encoding (int16 metres, -9999 = no
// data).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace globe::terrain {

// GTOPO30's no-data value; it marks sea, which the viewer and collision treat as 0 m.
inline constexpr int16_t kNoDataHeight = -9999;

// Vertices per side: 2^k + 1 so that a parent's vertices are every other vertex of its children.
bool isValidBlockSize(uint32_t verticesPerSide);

// Height of a GTOPO30 sample as a surface height: no-data (sea) is sea level.
constexpr double surfaceHeightMeters(int16_t sample) {
  return sample == kNoDataHeight ? 0.0 : static_cast<double>(sample);
}

struct HeightRange {
  int16_t minimumMeters = 0;
  int16_t maximumMeters = 0;
  void include(const HeightRange& other);
};

// Vertex (row, column): row 0 is the north edge, column 0 the west edge.
struct HeightBlock {
  uint32_t verticesPerSide = 0;
  std::vector<int16_t> heights;  // row-major, verticesPerSide^2 samples

  int16_t at(uint32_t row, uint32_t column) const {
    return heights[static_cast<size_t>(row) * verticesPerSide + column];
  }
  double surfaceHeightMetersAt(uint32_t row, uint32_t column) const {
    return surfaceHeightMeters(at(row, column));
  }
};

// Range of the block's surface heights, no-data counted as 0 m.
HeightRange surfaceHeightRange(const HeightBlock& block);

}  // namespace globe::terrain
