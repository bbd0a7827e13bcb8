// Heights of a pyramid's exact surface (collision's: the mesh the renderer draws) anywhere, from
// the finest tile present under a point, or the finest down to a chosen level; blocks read once
// and kept for the points around them. The one sampler of a pyramid's surface: exporters,
// elevation profiles and `globe play`'s log (where no drawn tile lies under the camera) use it.
// One per thread (it caches).
#pragma once

#include <cstdint>
#include <limits>
#include <list>
#include <memory>
#include <unordered_map>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"
#include "streaming/terrain_source.hpp"
#include "terrain/height_block.hpp"
#include "terrain/rendering_tile_array.hpp"

namespace globe::surface {

inline constexpr uint32_t kFinestLevel = std::numeric_limits<uint32_t>::max();

class PyramidSurface {
 public:
  PyramidSurface(streaming::TerrainSource& source, const geo::Ellipsoid& ellipsoid)
      : source_(source), ellipsoid_(ellipsoid) {}

  // The surface height at a point from the finest tile of level <= maxLevel there; 0 m where the
  // pyramid has none. Errors: unreadable packs, naming them.
  Result<double> heightMeters(double longitudeRadians, double latitudeRadians,
                              uint32_t maxLevel = kFinestLevel);
  // Whether the vertex nearest the point, of the finest tile of level <= maxLevel there, is
  // water (terrain::isWater): a water mask that agrees with the heights' vertices. False where
  // the pyramid has no tile.
  Result<bool> isWater(double longitudeRadians, double latitudeRadians,
                       uint32_t maxLevel = kFinestLevel);

  // A tile's block as the collision code reads it (its rectangle and highest vertex worked out
  // once when it loads, not at every point: an export asks for 65,536 points a tile).
  struct Loaded {
    std::shared_ptr<const terrain::HeightBlock> block;  // null: the pyramid has no such tile
    terrain::ArrayTile arrayTile{};
  };
  // The tile heightMeters samples at the point (block null where the pyramid has none), for
  // callers that sample many points of one tile (lattice_heights.hpp); the copy keeps the block
  // alive after the cache drops it.
  Result<Loaded> finestTile(double longitudeRadians, double latitudeRadians,
                            uint32_t maxLevel = kFinestLevel);
  // The level heightMeters starts its search at: maxLevel, or the pyramid's finest if coarser.
  uint32_t deepestLevel(uint32_t maxLevel) const;
  const geo::Ellipsoid& ellipsoid() const { return ellipsoid_; }

 private:
  static constexpr size_t kCachedBlocks = 512;
  Result<const Loaded*> block(const geo::TileId& tile);
  // The finest tile of level <= maxLevel under the point (null: none there).
  Result<const Loaded*> finest(double longitudeRadians, double latitudeRadians, uint32_t maxLevel);

  streaming::TerrainSource& source_;
  geo::Ellipsoid ellipsoid_;
  std::list<geo::TileId> recency_;  // most recent first
  struct Cached {
    Loaded loaded;
    std::list<geo::TileId>::iterator place;
  };
  std::unordered_map<geo::TileId, Cached> cache_;
};

}  // namespace globe::surface
