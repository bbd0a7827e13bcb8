// Quadtree navigation between a tile, its parent and its children.
#include "geo/tile_id.hpp"

namespace globe::geo {

TileId TileId::parent() const {
  if (level == 0) return *this;
  return {level - 1, x / 2, y / 2};
}

std::array<TileId, 4> TileId::children() const {
  const uint32_t childLevel = level + 1;
  const uint32_t west = 2 * x;
  const uint32_t north = 2 * y;
  return {TileId{childLevel, west, north}, TileId{childLevel, west + 1, north},
          TileId{childLevel, west, north + 1}, TileId{childLevel, west + 1, north + 1}};
}

std::string tileName(const TileId& tile) {
  return "tile " + std::to_string(tile.level) + "/" + std::to_string(tile.x) + "/" +
         std::to_string(tile.y);
}

}  // namespace globe::geo
