// A TIN tile's quadrant as its child's TIN, as CesiumJS upsamples a quantized-mesh tile the
// service lacks: the parent's triangles clipped to the child's rectangle (heights linear along
// their edges), so the child draws and collides with the parent's surface in as few triangles,
// not a resampled 65×65 grid.
#pragma once

#include <memory>

#include "geo/tile_id.hpp"
#include "terrain/tin_tile.hpp"

namespace globe::terrain {

// `child` must be a child of the parent's tile; nullptr when no triangle meets its quadrant.
std::shared_ptr<const TinTile> childTin(const TinTile& parent, const geo::TileId& child);

}  // namespace globe::terrain
