// Terrain height at a longitude/latitude from the rendering tile array, for `globe query`:
// QOTCD's conservative H or the exact rendered surface, with the tile that gave it.
#pragma once

#include <cstdint>
#include <optional>

#include "collision/exact_surface.hpp"
#include "collision/qotcd_height.hpp"
#include "collision/terrain_array.hpp"
#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"

namespace globe::collision {

enum class HeightMode { Qotcd, Exact };

struct HeightSample {
  double heightMeters = 0.0;
  geo::TileId tile{};
  uint32_t level = 0;                                // tile.level
  HeightCase heightCase = HeightCase::None;          // set in Qotcd mode
  SurfaceTriangle triangle = SurfaceTriangle::None;  // set in Exact mode
};

// The tile is found as by findIndexed; nullopt when none holds the point or the point is invalid
// (non-finite, |latitude| > pi/2). Any finite longitude is wrapped. The ellipsoid is used by
// Exact mode only (the mesh's ECEF vertices).
std::optional<HeightSample> sampleHeight(const RenderingTileArray& array,
                                         const geo::Ellipsoid& ellipsoid, double longitudeRadians,
                                         double latitudeRadians, HeightMode mode);

}  // namespace globe::collision
