// Identifies one tile of the geographic quadtree (see tiling_scheme.hpp) and hashes it.
#pragma once

#include <array>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace globe::geo {

// Deepest level of the quadtree: tilesX(30) = 2^31 still fits in a uint32_t.
inline constexpr uint32_t kMaxLevel = 30;

struct TileId {
  uint32_t level;
  uint32_t x;  // column, growing eastwards from -180 deg
  uint32_t y;  // row, growing southwards from +90 deg

  auto operator<=>(const TileId&) const = default;

  // The tile one level up that contains this one; a level-0 tile returns itself.
  TileId parent() const;
  // The four tiles one level down, in the order NW, NE, SW, SE (y grows southwards). Children of
  // a kMaxLevel tile are beyond kMaxLevel and therefore not valid tiles.
  std::array<TileId, 4> children() const;
};

// "tile L/X/Y", as messages name a tile.
std::string tileName(const TileId& tile);

}  // namespace globe::geo

// Collision-free for valid tiles: a unique quadtree index (tiles of all coarser levels first,
// then row-major) passed through the bijective splitmix64 finaliser for good bit mixing.
template <>
struct std::hash<globe::geo::TileId> {
  std::size_t operator()(const globe::geo::TileId& tile) const noexcept {
    uint64_t key = 0;
    if (tile.level <= globe::geo::kMaxLevel) {
      // Levels 0..L-1 hold 2 + 8 + ... = 2 (4^L - 1) / 3 tiles; the total stays below 2^62.
      const uint64_t tilesBefore = ((uint64_t{1} << (2 * tile.level)) - 1) / 3 * 2;
      key = tilesBefore + (uint64_t{tile.y} << (tile.level + 1)) + tile.x;
    } else {
      key = (uint64_t{tile.level} << 58) ^ (uint64_t{tile.y} << 29) ^ tile.x;
    }
    key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ULL;
    key = (key ^ (key >> 27)) * 0x94d049bb133111ebULL;
    return static_cast<std::size_t>(key ^ (key >> 31));
  }
};
