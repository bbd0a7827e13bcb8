#include "publish/pyramid_surface.hpp"

#include <algorithm>

#include "collision/exact_surface.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/rendering_tile_array.hpp"

namespace globe::publish {

Result<std::shared_ptr<const terrain::HeightBlock>> PyramidSurface::block(const geo::TileId& tile) {
  if (auto it = cache_.find(tile); it != cache_.end()) {
    recency_.splice(recency_.begin(), recency_, it->second.place);
    return it->second.block;
  }
  std::shared_ptr<const terrain::HeightBlock> loaded;
  auto summary = source_.summary(tile);
  if (!summary) return Error{summary.error()};
  if (*summary) {
    auto read = source_.loadBlock(tile);
    if (!read) return Error{read.error()};
    loaded = std::make_shared<const terrain::HeightBlock>(std::move(*read));
  }
  if (cache_.size() >= kCachedBlocks) {
    cache_.erase(recency_.back());
    recency_.pop_back();
  }
  recency_.push_front(tile);
  cache_.emplace(tile, Cached{loaded, recency_.begin()});
  return loaded;
}

Result<double> PyramidSurface::heightMeters(double longitudeRadians, double latitudeRadians,
                                            uint32_t maxLevel) {
  const double lon = geo::wrapLongitudeRadians(longitudeRadians);
  const uint32_t deepest = std::min(maxLevel, source_.manifest().maxLevel());
  for (uint32_t level = deepest + 1; level-- > 0;) {
    const auto tile = geo::GeographicTilingScheme::positionToTile(lon, latitudeRadians, level);
    if (!tile) return makeError("invalid position");
    auto found = block(*tile);
    if (!found) return Error{found.error()};
    if (!*found) continue;
    const terrain::ArrayTile arrayTile = terrain::makeArrayTile(*tile, **found);
    return collision::exactTileSurfaceHeight(arrayTile, ellipsoid_, lon, latitudeRadians)
        .heightMeters;
  }
  return 0.0;
}

}  // namespace globe::publish
