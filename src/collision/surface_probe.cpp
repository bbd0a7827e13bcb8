// QOTCD broad phase, exact (or QOTCD) narrow phase, triangle normals and vertex spacing.
#include "collision/surface_probe.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "collision/exact_surface.hpp"
#include "collision/qotcd.hpp"
#include "collision/qotcd_height.hpp"
#include "collision/terrain_array.hpp"
#include "geo/ecef.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"
#include "terrain/tin_tile.hpp"

namespace globe::collision {
namespace {

double modelHeight(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid, double longitudeRadians,
                   double latitudeRadians, SurfaceModel model) {
  if (model == SurfaceModel::Qotcd) {
    return qotcdTileHeight(tile, longitudeRadians, latitudeRadians).heightMeters;
  }
  return exactTileSurfaceHeight(tile, ellipsoid, longitudeRadians, latitudeRadians).heightMeters;
}

}  // namespace

namespace {

// The overlay's surface (3D Tiles) at a point, where there is one.
std::optional<double> overlayHeight(const RenderingTileArray& array, double lon, double lat) {
  return array.overlay() != nullptr ? array.overlay()->heightAt(lon, lat) : std::nullopt;
}

}  // namespace

SurfaceProbe probeSurface(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                          const geo::Cartographic& point, double clearanceMeters,
                          SurfaceModel model) {
  const double clearance = std::isfinite(clearanceMeters) ? clearanceMeters : 0.0;
  const QotcdResult quick = qotcdIndexed(array, point, clearance + kQotcdAllowanceMeters);
  SurfaceProbe probe;
  if (!quick.valid) return probe;
  probe.valid = true;
  probe.found = quick.found;
  probe.position = {quick.longitudeRadians, quick.latitudeRadians, quick.cameraHeightMeters};
  probe.tilesExamined = quick.tilesExamined;
  probe.surfaceHeightMeters = quick.terrainHeightMeters;
  if (quick.found) probe.tile = array.find(quick.tile);
  // A roof over the point that the camera is within its clearance of: the ground there is the
  // higher of it and the terrain.
  const auto over = overlayHeight(array, quick.longitudeRadians, quick.latitudeRadians);
  const bool overCollides = over && probe.position.heightMeters < *over + clearance;
  if (!quick.collided && !overCollides) return probe;
  // Narrow phase: QOTCD read the block (no early-out), or no tile holds the point (sea level).
  probe.surfaceRead = true;
  if (!quick.collided) {
    probe.surfaceHeightMeters = *over;  // above the terrain's upper bound QOTCD cleared
  } else if (probe.tile != nullptr) {
    probe.surfaceHeightMeters =
        modelHeight(*probe.tile, ellipsoid, quick.longitudeRadians, quick.latitudeRadians, model);
  }
  if (over) probe.surfaceHeightMeters = std::max(probe.surfaceHeightMeters, *over);
  probe.collided = probe.position.heightMeters < probe.surfaceHeightMeters + clearance;
  return probe;
}

std::optional<SurfaceHeight> surfaceHeightAt(const RenderingTileArray& array,
                                             const geo::Ellipsoid& ellipsoid,
                                             double longitudeRadians, double latitudeRadians,
                                             SurfaceModel model) {
  const std::optional<QueryPoint> point = makeQueryPoint(longitudeRadians, latitudeRadians);
  if (!point) return std::nullopt;
  SurfaceHeight height;
  height.tile = array.findIndexed(point->longitudeRadians, point->latitudeRadians);
  if (height.tile != nullptr) {
    height.found = true;
    height.heightMeters = modelHeight(*height.tile, ellipsoid, point->longitudeRadians,
                                      point->latitudeRadians, model);
  }
  const auto over = overlayHeight(array, point->longitudeRadians, point->latitudeRadians);
  if (over) height.heightMeters = std::max(height.heightMeters, *over);
  return height;
}

glm::dvec3 surfaceNormalAt(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                           double longitudeRadians, double latitudeRadians) {
  const std::optional<QueryPoint> point = makeQueryPoint(longitudeRadians, latitudeRadians);
  if (!point) return {0.0, 0.0, 1.0};
  const glm::dvec3 up = geo::geodeticSurfaceNormal(
      ellipsoid, geo::Cartographic{point->longitudeRadians, point->latitudeRadians, 0.0});
  const ArrayTile* tile = array.findIndexed(point->longitudeRadians, point->latitudeRadians);
  const auto over = overlayHeight(array, point->longitudeRadians, point->latitudeRadians);
  if (tile == nullptr) return up;
  const SurfaceSample sample =
      exactTileSurfaceHeight(*tile, ellipsoid, point->longitudeRadians, point->latitudeRadians);
  // Over a roof the ground is the roof, taken as level (its grid keeps heights, not slopes).
  if (over && *over > sample.heightMeters) return up;
  auto facingUp = [&up](const std::array<glm::dvec3, 3>& p) {
    const glm::dvec3 normal = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double length = glm::length(normal);
    if (!(length > 0.0) || !std::isfinite(length)) return up;
    const glm::dvec3 unit = normal / length;
    return glm::dot(unit, up) < 0.0 ? -unit : unit;
  };
  if (sample.triangle == SurfaceTriangle::Tin) {
    return facingUp(tile->block->tin->triangleEcefMeters(ellipsoid, sample.quadRow));
  }
  if (sample.triangle != SurfaceTriangle::SouthWest &&
      sample.triangle != SurfaceTriangle::NorthEast) {
    return up;
  }
  // SW: (i,j), (i+1,j), (i+1,j+1); NE: (i,j), (i+1,j+1), (i,j+1) (tile_mesh.hpp's diagonal rule).
  const uint32_t i = sample.quadRow, j = sample.quadColumn;
  const std::array<std::array<uint32_t, 2>, 3> corners =
      sample.triangle == SurfaceTriangle::SouthWest
          ? std::array<std::array<uint32_t, 2>, 3>{{{i, j}, {i + 1, j}, {i + 1, j + 1}}}
          : std::array<std::array<uint32_t, 2>, 3>{{{i, j}, {i + 1, j + 1}, {i, j + 1}}};
  const terrain::BlockGrid grid{tile->id, tile->block->verticesPerSide};
  std::array<glm::dvec3, 3> p{};
  for (size_t k = 0; k < 3; ++k) {
    const uint32_t row = corners[k][0], column = corners[k][1];
    p[k] = terrain::tileVertexEcefMeters(ellipsoid, grid, row, column,
                                         tile->block->surfaceHeightMetersAt(row, column));
  }
  return facingUp(p);
}

double vertexSpacingMeters(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid) {
  const uint32_t n = tile.block != nullptr ? tile.block->verticesPerSide : 2;
  const double degrees = terrain::vertexSpacingDegrees(tile.id.level, std::max(n, 2u));
  return geo::degreesToRadians(degrees) * ellipsoid.semiMajorAxisMeters;
}

double maximumSurfaceHeightMeters(const RenderingTileArray& array) {
  double highest =
      array.overlay() != nullptr ? std::max(0.0, array.overlay()->maximumHeightMeters()) : 0.0;
  for (const ArrayTile& tile : array.tiles()) {
    highest = std::max(highest, static_cast<double>(tile.maximumHeightMeters));
  }
  return highest;
}

}  // namespace globe::collision
