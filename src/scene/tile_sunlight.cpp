#include "scene/tile_sunlight.hpp"

#include <cmath>

#include "collision/sun_visibility.hpp"

namespace globe::scene {
namespace {

// The Sun's direction rounded to ~0.05° (1/1200 of a radian): a move smaller than a tenth of its
// disc keeps the shadows.
constexpr double kKeyPerUnit = 1200.0;

}  // namespace

size_t TileSunlight::update(const terrain::RenderingTileArray& array,
                            const geo::Ellipsoid& ellipsoid, const glm::dvec3& sunDirectionEcef,
                            TileGpu& gpu, uint32_t tilesPerFrame, bool settled) {
  const SunKey key{static_cast<int32_t>(std::lround(sunDirectionEcef.x * kKeyPerUnit)),
                   static_cast<int32_t>(std::lround(sunDirectionEcef.y * kKeyPerUnit)),
                   static_cast<int32_t>(std::lround(sunDirectionEcef.z * kKeyPerUnit))};
  size_t stale = 0;
  uint32_t done = 0;
  for (const terrain::ArrayTile& tile : array.tiles()) {
    if (!tile.drawn) continue;
    const auto known = sunKeys_.find(tile.id);
    if (known != sunKeys_.end() && known->second == key) continue;
    if (!settled || (tilesPerFrame != 0 && done >= tilesPerFrame)) {
      ++stale;
      continue;
    }
    const auto visibility =
        collision::tileSunVisibility(tile, array, ellipsoid, sunDirectionEcef);
    if (gpu.prepareTileSunlight(tile.id, visibility)) sunKeys_[tile.id] = key;
    ++done;
  }
  return stale;
}

}  // namespace globe::scene
