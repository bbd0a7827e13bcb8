// The geographic (longitude/latitude quadtree) tiling scheme: which tiles exist, where they
// are, and which tile holds a position.
#pragma once

#include <cstdint>
#include <optional>

#include "geo/globe_rectangle.hpp"
#include "geo/tile_id.hpp"

namespace globe::geo {

// Level 0 is two 180x180 deg tiles (x = 0: -180..0, x = 1: 0..180); each level splits every
// tile in four. x grows eastwards from -180 deg, y grows SOUTHWARDS from +90 deg (row 0 is the
// northernmost, matching GTOPO30 row order). Levels go from 0 to kMaxLevel (tile_id.hpp).
//
// Edge rule: tiles are half-open, [west, east) x (south, north], so a point exactly on an edge
// shared by two tiles belongs to the tile to its east / to its south. Exceptions: longitude
// +180 deg belongs to the easternmost column and latitude -90 deg to the southernmost row.
// Longitudes outside [-pi, pi] are wrapped first (wrapLongitudeRadians).
//
// Edges are computed as -pi + x * (2 pi / tilesX) and pi/2 - y * (pi / tilesY), and
// positionToTile uses the very same expressions, so the two agree to the last bit: a tile's
// own west/north corner maps back to it, and positionToTile(p) is a tile whose (closed)
// rectangle contains p. Edges are also identical across levels (a parent's edges are its
// children's), and the outermost edges are exactly -pi, pi, -pi/2 and pi/2.
class GeographicTilingScheme {
 public:
  // 2^(level+1) columns and 2^level rows; 0 for level > kMaxLevel.
  static uint32_t tilesX(uint32_t level);
  static uint32_t tilesY(uint32_t level);

  static bool isValid(const TileId& tile);
  // The tile's footprint; meaningless for invalid tiles.
  static GlobeRectangle tileRectangle(const TileId& tile);
  // The tile containing the position at that level, in O(1); nullopt for non-finite input,
  // |latitude| > pi/2 or level > kMaxLevel.
  static std::optional<TileId> positionToTile(double longitudeRadians, double latitudeRadians,
                                              uint32_t level);
};

}  // namespace globe::geo
