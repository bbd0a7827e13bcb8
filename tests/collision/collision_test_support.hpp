// Test support for collision: synthetic blocks and arrays, the bundled real pyramid (tiled once
// per run) with cached blocks, real arrays (whole levels, quadtree cuts), and query points that
// hit tile edges, corners, vertices, +-180 deg and the poles exactly.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <unordered_map>
#include <vector>

#include "collision/terrain_array.hpp"
#include "geo/tile_id.hpp"
#include "streaming/tile_store.hpp"
#include "terrain/height_block.hpp"

namespace globe::collision::testing {

// A sample value that differs at every (row i, column j) of a 17x17 block: 100 i + j.
inline int16_t distinct(uint32_t i, uint32_t j) { return static_cast<int16_t>(100 * i + j); }

// An N x N block with heights h(row, column).
terrain::HeightBlock makeBlock(uint32_t verticesPerSide,
                               const std::function<int16_t(uint32_t, uint32_t)>& height);
// A rendering tile array over the tiles, all sharing one block.
RenderingTileArray arrayOf(const std::vector<geo::TileId>& tiles,
                           const terrain::HeightBlock& block);

// Longitude / latitude of grid point (row + s, column + t) of a tile, from its radian bounds;
// the last line is exactly the tile's east / south edge.
double gridLongitude(const geo::TileId& tile, uint32_t verticesPerSide, double column);
double gridLatitude(const geo::TileId& tile, uint32_t verticesPerSide, double row);
// The mesh's own vertex position (terrain::BlockGrid degrees, converted to radians).
double meshVertexLongitude(const geo::TileId& tile, uint32_t verticesPerSide, uint32_t column);
double meshVertexLatitude(const geo::TileId& tile, uint32_t verticesPerSide, uint32_t row);

// The bundled pyramid (ETOPO20 + W002N52 + Fuji, WGS84), read through io::TileStore.
class RealPyramid {
 public:
  static RealPyramid& bundled();
  // ETOPO20 + the bundled Zion SRTM 3" (data/dem/zion-srtm3.tif): real canyon walls.
  static RealPyramid& zion();
  bool has(const geo::TileId& tile);
  // The tile's block, loaded once and kept (the reference stays valid).
  const terrain::HeightBlock& block(const geo::TileId& tile);
  ArrayTile arrayTile(const geo::TileId& tile) { return makeArrayTile(tile, block(tile)); }
  RenderingTileArray array(const std::vector<geo::TileId>& tiles);
  uint32_t maxLevel() const { return store_->manifest().maxLevel(); }
  uint32_t verticesPerSide() const { return store_->manifest().verticesPerSide; }
  // A random existing tile of the level, drawn over the sources fine enough for it.
  geo::TileId randomTile(std::mt19937_64& rng, uint32_t level);

 private:
  explicit RealPyramid(std::unique_ptr<streaming::TileStore> store) : store_(std::move(store)) {}
  std::unique_ptr<streaming::TileStore> store_;
  std::unordered_map<geo::TileId, bool> exists_;
  std::unordered_map<geo::TileId, terrain::HeightBlock> blocks_;
};

// Every tile of a level whose rectangle intersects the rectangle (degrees) and that exists.
std::vector<geo::TileId> tilesOfLevel(RealPyramid& pyramid, uint32_t level, double westDegrees,
                                      double southDegrees, double eastDegrees, double northDegrees);
// A quadtree cut from the two roots: a tile is refined (into its four children, which the
// pyramid must have) when refine(tile) says so. The tiles cover the globe without overlapping.
std::vector<geo::TileId> quadtreeCut(RealPyramid& pyramid,
                                     const std::function<bool(const geo::TileId&)>& refine);

struct LonLat {
  double longitudeRadians;
  double latitudeRadians;
};
// A random point, mixing: uniform over the globe; inside a tile of `tiles`; exactly on an edge
// or corner of a tile of `tiles` or of any tile up to maxLevel (tiling-scheme radians); on a
// mesh vertex (block-grid degrees); longitude exactly +-180 deg; latitude exactly +-90 deg.
LonLat randomQueryPoint(std::mt19937_64& rng, const std::vector<geo::TileId>& tiles,
                        uint32_t maxLevel, uint32_t verticesPerSide);

}  // namespace globe::collision::testing
