// sampleHeight: the indexed tile lookup followed by the QOTCD or exact height in that tile.
#include "collision/height_service.hpp"

#include "collision/terrain_array.hpp"

namespace globe::collision {

std::optional<HeightSample> sampleHeight(const RenderingTileArray& array,
                                         const geo::Ellipsoid& ellipsoid, double longitudeRadians,
                                         double latitudeRadians, HeightMode mode) {
  const std::optional<QueryPoint> point = makeQueryPoint(longitudeRadians, latitudeRadians);
  if (!point) return std::nullopt;
  const ArrayTile* tile = array.findIndexed(point->longitudeRadians, point->latitudeRadians);
  if (tile == nullptr) return std::nullopt;
  HeightSample sample;
  sample.tile = tile->id;
  sample.level = tile->id.level;
  if (mode == HeightMode::Qotcd) {
    const TileHeight height =
        qotcdTileHeight(*tile, point->longitudeRadians, point->latitudeRadians);
    sample.heightMeters = height.heightMeters;
    sample.heightCase = height.heightCase;
  } else {
    const SurfaceSample surface =
        exactTileSurfaceHeight(*tile, ellipsoid, point->longitudeRadians, point->latitudeRadians);
    sample.heightMeters = surface.heightMeters;
    sample.triangle = surface.triangle;
  }
  return sample;
}

}  // namespace globe::collision
