#include "wanted_tiles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geo/tiling_scheme.hpp"

namespace globe::bench {
namespace {

constexpr double kEquatorMeters = 40'075'016.7;

bool insideLevelBounds(const geo::TileId& tile, const formats::BoundsDegrees& bounds) {
  const geo::GlobeRectangle r = geo::GeographicTilingScheme::tileRectangle(tile);
  return r.intersects(
      geo::GlobeRectangle::fromDegrees(bounds.west, bounds.south, bounds.east, bounds.north));
}

}  // namespace

uint32_t finestLevelForHeight(double heightMeters, uint32_t maxLevel) {
  // Level L has 2^(L+1) tiles around the equator.
  const double columns = kEquatorMeters / std::max(heightMeters, 1.0);
  const double level = std::floor(std::log2(columns)) - 1;
  return static_cast<uint32_t>(std::clamp(level, 0.0, static_cast<double>(maxLevel)));
}

std::vector<streaming::LoadRequest> wantedTiles(const CameraSample& camera,
                                                const formats::PyramidManifest& manifest) {
  std::vector<streaming::LoadRequest> wanted;
  const uint32_t finest = finestLevelForHeight(camera.heightMeters, manifest.maxLevel());
  for (uint32_t k = 0; k < kLevelsWanted && k <= finest; ++k) {
    const uint32_t level = finest - k;
    const auto centre = geo::GeographicTilingScheme::positionToTile(camera.longitudeRadians,
                                                                    camera.latitudeRadians, level);
    if (!centre) continue;
    const auto columns = static_cast<int64_t>(geo::GeographicTilingScheme::tilesX(level));
    const auto rows = static_cast<int64_t>(geo::GeographicTilingScheme::tilesY(level));
    for (int64_t dy = -1; dy <= 1; ++dy) {
      const int64_t y = centre->y + dy;
      if (y < 0 || y >= rows) continue;
      for (int64_t dx = -1; dx <= 1; ++dx) {
        const int64_t x = ((centre->x + dx) % columns + columns) % columns;  // wraps at 180°
        const geo::TileId tile{level, static_cast<uint32_t>(x), static_cast<uint32_t>(y)};
        if (!insideLevelBounds(tile, manifest.levels[level].bounds)) continue;
        // Coarser levels first (they are what is drawn until the finer ones arrive), then the
        // centre before its neighbours.
        const double priority = -2.0 * level - (dx == 0 && dy == 0 ? 0.0 : 1.0);
        wanted.push_back({tile, priority});
      }
    }
  }
  return wanted;
}

}  // namespace globe::bench
