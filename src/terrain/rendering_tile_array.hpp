// The rendering tile array as collision sees it: the tiles drawn this frame with their blocks,
// and an index (TileId hash, levels present, pole tiles) for O(1)-per-level lookups.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "geo/tile_id.hpp"
#include "terrain/height_block.hpp"
#include "terrain/surface_overlay.hpp"

namespace globe::terrain {

struct QueryPoint;  // tile_containment.hpp

// One drawn tile. The bounds must be exactly GeographicTilingScheme::tileRectangle(id) (closed:
// a point on an edge is in the tile). The block is owned elsewhere and must outlive the array.
// maximumHeightMeters must be >= every vertex's surface height (sea = 0 m): the early-out trusts
// it.
struct ArrayTile {
  geo::TileId id{};
  double westRadians = 0.0;
  double southRadians = 0.0;
  double eastRadians = 0.0;
  double northRadians = 0.0;
  const HeightBlock* block = nullptr;
  int16_t maximumHeightMeters = 0;
  // False for a tile collision holds but the frame does not draw (the ground under a camera
  // looking away from it, scene/terrain_scene.cpp): collision uses it all the same.
  bool drawn = true;
};

// True when the tile has a block of N x N heights with N >= 2: the functions that read a tile
// (collision's locateInGrid, qotcdTileHeight, exactTileSurfaceHeight) need one;
// RenderingTileArray::assign admits only such tiles.
inline bool hasReadableBlock(const ArrayTile& tile) {
  if (tile.block == nullptr) return false;
  const size_t n = tile.block->verticesPerSide;
  return n >= 2 && tile.block->heights.size() == n * n;
}

// An ArrayTile with the scheme's bounds and the block's maximum surface height.
ArrayTile makeArrayTile(const geo::TileId& id, const HeightBlock& block);

// Result of a tile lookup: the tile (nullptr if none contains the point) and how many tiles were
// examined (bounds tests for the linear scan, hash probes for the indexed lookup).
struct TileLookup {
  const ArrayTile* tile = nullptr;
  uint32_t tilesExamined = 0;
};

// Which tile holds a point (both lookups give the same tile; rules in tile_containment.hpp):
// among the tiles whose closed bounds contain it (+-180 deg are one meridian; a pole lies in
// every tile of the polar row), the finest level wins; within a level, the tile owning the point
// by the scheme's half-open edge rule, else the southern, else the eastern one; at a pole, the
// tile owning the longitude, else the westernmost (smallest x).
class RenderingTileArray {
 public:
  // Replaces the contents and rebuilds the index. Tiles with an invalid id, no block, a block
  // whose size is not 2^k+1 or whose heights are not N^2, bounds other than tileRectangle(id),
  // or an id already present are dropped and counted in rejectedTileCount().
  void assign(std::vector<ArrayTile> tiles);

  std::span<const ArrayTile> tiles() const { return tiles_; }
  // What is drawn over the terrain and collided with as ground (3D Tiles); kept across assign().
  void setOverlay(std::shared_ptr<const SurfaceOverlay> overlay) { overlay_ = std::move(overlay); }
  const SurfaceOverlay* overlay() const { return overlay_.get(); }
  uint32_t rejectedTileCount() const { return rejected_; }
  // The levels present, finest first.
  std::span<const uint32_t> levelsFinestFirst() const { return levels_; }
  const ArrayTile* find(const geo::TileId& id) const;
  // Heap bytes of the tile index (for memory reports; the tile records are tiles().size() x
  // sizeof(ArrayTile)).
  size_t indexMemoryBytes() const;

  // The paper's lookup: compares the point with the bounds of every tile. O(tiles).
  TileLookup lookupLinear(double longitudeRadians, double latitudeRadians) const;
  // The same tile from the tile ids of the point at each level present (finest first), with the
  // edge neighbours when the point lies exactly on an edge. O(levels present).
  TileLookup lookupIndexed(double longitudeRadians, double latitudeRadians) const;
  // The same for a point already in canonical form (makeQueryPoint), as QOTCD has it.
  TileLookup lookupIndexed(const QueryPoint& point) const;
  const ArrayTile* findLinear(double longitudeRadians, double latitudeRadians) const {
    return lookupLinear(longitudeRadians, latitudeRadians).tile;
  }
  const ArrayTile* findIndexed(double longitudeRadians, double latitudeRadians) const {
    return lookupIndexed(longitudeRadians, latitudeRadians).tile;
  }

 private:
  std::vector<ArrayTile> tiles_;
  std::shared_ptr<const SurfaceOverlay> overlay_;
  // The index: open addressing with linear probing over a power-of-two table (load <= 2/3) of
  // (quadtree key, position) slots, so a lookup is a mix, a mask and usually one cache line.
  static constexpr uint64_t kEmptyKey = UINT64_MAX;  // quadtree keys are < 2^62
  struct Slot {
    uint64_t key = kEmptyKey;
    uint32_t position = 0;
  };
  std::vector<Slot> slots_;
  uint64_t slotMask_ = 0;
  uint32_t findPosition(const geo::TileId& id) const;
  // lookupIndexed beyond its common case: poles, edges, a finest owner that is not drawn.
  TileLookup lookupAcrossLevels(const QueryPoint& point, const geo::TileId& finestOwner,
                                const ArrayTile* finestOwnerTile) const;
  bool insertPosition(const geo::TileId& id, uint32_t position);
  std::vector<uint32_t> levels_;
  // Per level, the position of the westernmost tile of the northernmost / southernmost row, or
  // kNoTile (positions, not pointers, so that copies of the array stay valid).
  static constexpr uint32_t kNoTile = UINT32_MAX;
  std::array<uint32_t, geo::kMaxLevel + 1> northPoleTiles_{};
  std::array<uint32_t, geo::kMaxLevel + 1> southPoleTiles_{};
  const ArrayTile* at(uint32_t position) const {
    return position == kNoTile ? nullptr : &tiles_[position];
  }
  uint32_t rejected_ = 0;
};

}  // namespace globe::terrain
