#include "buildings/building_quadtree.hpp"

#include <array>

namespace globe::buildings {
namespace {

void split(std::vector<QuadtreeCell>& cells, size_t at, std::span<const ExtentDegrees> items,
           const QuadtreeLimits& limits) {
  if (cells[at].items.size() <= limits.maxItemsPerCell || cells[at].level >= limits.maxLevel) {
    return;
  }
  const QuadtreeCell parent = cells[at];
  const double midX = (parent.extent.west + parent.extent.east) / 2;
  const double midY = (parent.extent.south + parent.extent.north) / 2;
  std::array<QuadtreeCell, 4> quarters;
  for (uint32_t q = 0; q < 4; ++q) {
    const uint32_t dx = q % 2, dy = q / 2;  // dy 0: the northern half
    QuadtreeCell& c = quarters[q];
    c.level = parent.level + 1, c.x = 2 * parent.x + dx, c.y = 2 * parent.y + dy;
    c.extent = {dx == 0 ? parent.extent.west : midX, dy == 0 ? midY : parent.extent.south,
                dx == 0 ? midX : parent.extent.east, dy == 0 ? parent.extent.north : midY};
  }
  std::vector<size_t> stay;
  for (const size_t item : parent.items) {
    bool placed = false;
    for (QuadtreeCell& q : quarters) {
      if (q.extent.contains(items[item])) {
        q.items.push_back(item);
        placed = true;
        break;
      }
    }
    if (!placed) stay.push_back(item);
  }
  cells[at].items = std::move(stay);
  for (QuadtreeCell& q : quarters) {
    if (q.items.empty()) continue;
    const size_t child = cells.size();
    cells.push_back(std::move(q));
    cells[at].children.push_back(child);
    split(cells, child, items, limits);
  }
}

}  // namespace

std::vector<QuadtreeCell> partitionBuildings(std::span<const ExtentDegrees> items,
                                             const ExtentDegrees& bounds,
                                             const QuadtreeLimits& limits) {
  std::vector<QuadtreeCell> cells(1);
  cells[0].extent = bounds;
  for (size_t i = 0; i < items.size(); ++i) cells[0].items.push_back(i);
  split(cells, 0, items, limits);
  return cells;
}

}  // namespace globe::buildings
