#include "surface/pyramid_surface.hpp"

#include <algorithm>
#include <cmath>

#include "collision/exact_surface.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/rendering_tile_array.hpp"

namespace globe::surface {

Result<const PyramidSurface::Loaded*> PyramidSurface::block(const geo::TileId& tile) {
  if (auto it = cache_.find(tile); it != cache_.end()) {
    recency_.splice(recency_.begin(), recency_, it->second.place);
    return &it->second.loaded;
  }
  Loaded loaded;
  auto summary = source_.summary(tile);
  if (!summary) return Error{summary.error()};
  if (*summary) {
    auto read = source_.loadBlock(tile);
    if (!read) return Error{read.error()};
    loaded.block = std::make_shared<const terrain::HeightBlock>(std::move(*read));
    loaded.arrayTile = terrain::makeArrayTile(tile, *loaded.block);
  }
  if (cache_.size() >= kCachedBlocks) {
    cache_.erase(recency_.back());
    recency_.pop_back();
  }
  recency_.push_front(tile);
  return &cache_.emplace(tile, Cached{std::move(loaded), recency_.begin()}).first->second.loaded;
}

Result<const PyramidSurface::Loaded*> PyramidSurface::finest(double longitudeRadians,
                                                             double latitudeRadians,
                                                             uint32_t maxLevel) {
  for (uint32_t level = deepestLevel(maxLevel) + 1; level-- > 0;) {
    const auto tile =
        geo::GeographicTilingScheme::positionToTile(longitudeRadians, latitudeRadians, level);
    if (!tile) return makeError("invalid position");
    auto found = block(*tile);
    if (!found) return Error{found.error()};
    if ((*found)->block) return *found;
  }
  return static_cast<const Loaded*>(nullptr);
}

uint32_t PyramidSurface::deepestLevel(uint32_t maxLevel) const {
  return std::min(maxLevel, source_.manifest().maxLevel());
}

Result<PyramidSurface::Loaded> PyramidSurface::finestTile(double longitudeRadians,
                                                          double latitudeRadians,
                                                          uint32_t maxLevel) {
  auto found = finest(geo::wrapLongitudeRadians(longitudeRadians), latitudeRadians, maxLevel);
  if (!found) return Error{found.error()};
  if (*found == nullptr) return Loaded{};
  return **found;
}

Result<double> PyramidSurface::heightMeters(double longitudeRadians, double latitudeRadians,
                                            uint32_t maxLevel) {
  const double lon = geo::wrapLongitudeRadians(longitudeRadians);
  auto found = finest(lon, latitudeRadians, maxLevel);
  if (!found) return Error{found.error()};
  if (*found == nullptr) return 0.0;
  return collision::exactTileSurfaceHeight((*found)->arrayTile, ellipsoid_, lon, latitudeRadians)
      .heightMeters;
}

Result<bool> PyramidSurface::isWater(double longitudeRadians, double latitudeRadians,
                                     uint32_t maxLevel) {
  const double lon = geo::wrapLongitudeRadians(longitudeRadians);
  auto found = finest(lon, latitudeRadians, maxLevel);
  if (!found) return Error{found.error()};
  if (*found == nullptr) return false;
  const terrain::HeightBlock& block = *(*found)->block;
  const auto rect = geo::GeographicTilingScheme::tileRectangle((*found)->arrayTile.id);
  const uint32_t n = block.verticesPerSide;
  const auto nearest = [&](double fraction) {
    return static_cast<size_t>(std::clamp(std::lround(fraction * (n - 1)), 0L, long{n} - 1));
  };
  const size_t column = nearest((lon - rect.westRadians) / (rect.eastRadians - rect.westRadians));
  const size_t row =
      nearest((rect.northRadians - latitudeRadians) / (rect.northRadians - rect.southRadians));
  return terrain::isWater(block.heights[row * n + column]);
}

}  // namespace globe::surface
