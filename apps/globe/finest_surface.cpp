// The finest pyramid tile under a point, its block read once, and its exact mesh height.
#include "apps/globe/finest_surface.hpp"

#include "collision/exact_surface.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/rendering_tile_array.hpp"

namespace globe::app {

Result<double> FinestSurface::heightMeters(double longitudeRadians, double latitudeRadians) {
  const double lon = geo::wrapLongitudeRadians(longitudeRadians);
  for (uint32_t level = store_.manifest().maxLevel() + 1; level-- > 0;) {
    const auto tile = geo::GeographicTilingScheme::positionToTile(lon, latitudeRadians, level);
    if (!tile) return makeError("invalid position");
    if (tile_ != *tile) {
      auto summary = store_.summary(*tile);
      if (!summary) return Error{summary.error()};
      if (!*summary) continue;
      auto block = store_.loadBlock(*tile);
      if (!block) return Error{block.error()};
      block_ = std::move(*block);
      tile_ = *tile;
    }
    const terrain::ArrayTile arrayTile = terrain::makeArrayTile(*tile_, block_);
    return collision::exactTileSurfaceHeight(arrayTile, ellipsoid_, lon, latitudeRadians)
        .heightMeters;
  }
  return 0.0;
}

}  // namespace globe::app
