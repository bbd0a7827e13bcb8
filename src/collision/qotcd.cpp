// QOTCD's three steps (camera to geodetic, tile and height, comparison), linear or indexed.
#include "collision/qotcd.hpp"

#include <cmath>
#include <optional>

#include "collision/terrain_array.hpp"
#include "geo/ecef.hpp"

namespace globe::collision {
namespace {

enum class Lookup { Linear, Indexed };

// A template on the lookup, so the indexed query carries no linear code.
template <Lookup lookup>
QotcdResult detect(const RenderingTileArray& array, const geo::Cartographic& camera,
                   double clearanceMeters) {
  if (!std::isfinite(camera.heightMeters)) return {};
  const std::optional<QueryPoint> point =
      makeQueryPoint(camera.longitudeRadians, camera.latitudeRadians);
  if (!point) return {};
  const double clearance = std::isfinite(clearanceMeters) ? clearanceMeters : 0.0;

  QotcdResult result;
  result.valid = true;
  result.cameraHeightMeters = camera.heightMeters;
  result.longitudeRadians = point->longitudeRadians;
  result.latitudeRadians = point->latitudeRadians;
  TileLookup found;
  if constexpr (lookup == Lookup::Linear) {
    found = array.lookupLinear(point->longitudeRadians, point->latitudeRadians);
  } else {
    found = array.lookupIndexed(*point);
  }
  result.tilesExamined = found.tilesExamined;
  if (found.tile != nullptr) {
    const ArrayTile& tile = *found.tile;
    result.found = true;
    result.tile = tile.id;
    if (result.cameraHeightMeters > tile.maximumHeightMeters + clearance) {
      result.earlyOut = true;
      result.terrainHeightMeters = tile.maximumHeightMeters;
      result.heightCase = HeightCase::TileMaximum;
    } else {
      const TileHeight height =
          qotcdTileHeight(tile, point->longitudeRadians, point->latitudeRadians);
      result.terrainHeightMeters = height.heightMeters;
      result.heightCase = height.heightCase;
    }
  }
  result.collided = result.cameraHeightMeters <= result.terrainHeightMeters + clearance;
  return result;
}

template <Lookup lookup>
QotcdResult detect(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                   const glm::dvec3& cameraEcefMeters, double clearanceMeters) {
  const std::optional<geo::Cartographic> camera =
      geo::ecefToCartographic(ellipsoid, cameraEcefMeters);
  if (!camera) return {};
  return detect<lookup>(array, *camera, clearanceMeters);
}

}  // namespace

QotcdResult qotcdLinear(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                        const glm::dvec3& cameraEcefMeters, double clearanceMeters) {
  return detect<Lookup::Linear>(array, ellipsoid, cameraEcefMeters, clearanceMeters);
}

QotcdResult qotcdIndexed(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                         const glm::dvec3& cameraEcefMeters, double clearanceMeters) {
  return detect<Lookup::Indexed>(array, ellipsoid, cameraEcefMeters, clearanceMeters);
}

QotcdResult qotcdLinear(const RenderingTileArray& array, const geo::Cartographic& camera,
                        double clearanceMeters) {
  return detect<Lookup::Linear>(array, camera, clearanceMeters);
}

QotcdResult qotcdIndexed(const RenderingTileArray& array, const geo::Cartographic& camera,
                         double clearanceMeters) {
  return detect<Lookup::Indexed>(array, camera, clearanceMeters);
}

void QotcdCounters::add(const QotcdResult& result) {
  ++queries;
  tilesExamined += result.tilesExamined;
  if (!result.valid) {
    ++invalid;
    return;
  }
  if (!result.found) ++notFound;
  if (result.collided) ++collisions;
  if (result.earlyOut) ++earlyOuts;
  if (result.heightCase != HeightCase::None && !result.earlyOut) ++blockReads;
}

}  // namespace globe::collision
