// Buildings partitioned by a quadtree of their extent, for a tileset refined by ADD: each
// building is stored once, in the deepest cell that holds its whole footprint; a cell with more
// than a tile's worth splits into four, and what straddles its children stays in it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "buildings/footprint.hpp"

namespace globe::buildings {

struct QuadtreeCell {
  uint32_t level = 0, x = 0, y = 0;  // x eastward, y southward from the root's north-west
  ExtentDegrees extent;
  std::vector<size_t> items;     // indices of the buildings stored here
  std::vector<size_t> children;  // indices of non-empty child cells
};

struct QuadtreeLimits {
  size_t maxItemsPerCell = 1000;  // a cell with more splits
  uint32_t maxLevel = 12;         // below the root; cells there never split
};

// cells[0] is the root, covering `bounds`; every item index appears in exactly one cell, and
// cells that would hold nothing (with nothing below them) are left out. Items that lie outside
// `bounds` stay in the root.
std::vector<QuadtreeCell> partitionBuildings(std::span<const ExtentDegrees> items,
                                             const ExtentDegrees& bounds,
                                             const QuadtreeLimits& limits);

}  // namespace globe::buildings
