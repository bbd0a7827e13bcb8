// The drawn triangles under the eye's ball: closest points (Ericson, Real-Time Collision
// Detection 5.1.5) in eye-relative coordinates, so nothing is lost to the ~6.4e6 m translation.
#include "collision/lateral_clearance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "collision/clearance_settings.hpp"
#include "collision/grid_location.hpp"
#include "collision/terrain_array.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"
#include "terrain/tin_tile.hpp"

namespace globe::collision {
namespace {

// The point of triangle abc nearest the origin.
glm::dvec3 closestToOrigin(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = -a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const glm::dvec3 bp = -b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const glm::dvec3 cp = -c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  }
  const double denominator = va + vb + vc;
  if (!(std::abs(denominator) > 0)) return a;  // degenerate: a is as good as any
  return a + ab * (vb / denominator) + ac * (vc / denominator);
}

// The longitude nearest `reference` among lon + k 2 pi.
double nearLongitude(double longitudeRadians, double referenceRadians) {
  return referenceRadians +
         std::remainder(longitudeRadians - referenceRadians, 2 * std::numbers::pi);
}

}  // namespace

std::optional<NearestTriangle> nearestDrawnTriangle(const RenderingTileArray& array,
                                                    const geo::Ellipsoid& ellipsoid,
                                                    const glm::dvec3& eyeEcefMeters,
                                                    double radiusMeters) {
  if (!(radiusMeters > 0) || !std::isfinite(radiusMeters)) return std::nullopt;
  const auto eye = geo::ecefToCartographic(ellipsoid, eyeEcefMeters);
  if (!eye) return std::nullopt;
  // The ball's footprint as a longitude/latitude box (generous: the ellipsoid's smallest
  // radius of curvature is > 6.3e6 m, so 6.3e6 over-covers), clamped at the poles.
  const double lat = eye->latitudeRadians, lon = eye->longitudeRadians;
  const double dLat = radiusMeters / 6.3e6;
  const double cosLat = std::cos(std::min(std::abs(lat) + dLat, std::numbers::pi / 2));
  const double dLon = cosLat > 1e-9 ? std::min(radiusMeters / (6.3e6 * cosLat), std::numbers::pi)
                                    : std::numbers::pi;
  const double south = std::max(lat - dLat, -std::numbers::pi / 2);
  const double north = std::min(lat + dLat, std::numbers::pi / 2);

  // The tiles under the box: those holding a 3x3 grid of its points (the box is far smaller
  // than a tile at any level whose cells it could reach).
  std::vector<const ArrayTile*> tiles;
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      const auto point =
          makeQueryPoint(lon + (b - 1) * dLon, std::clamp(lat + (a - 1) * dLat, south, north));
      if (!point) continue;
      const ArrayTile* tile = array.findIndexed(point->longitudeRadians, point->latitudeRadians);
      if (tile != nullptr && hasReadableBlock(*tile) &&
          std::find(tiles.begin(), tiles.end(), tile) == tiles.end()) {
        tiles.push_back(tile);
      }
    }
  }

  NearestTriangle nearest;
  nearest.distanceMeters = radiusMeters;
  bool found = false;
  for (const ArrayTile* tile : tiles) {
    const geo::GlobeRectangle r = geo::GeographicTilingScheme::tileRectangle(tile->id);
    const double centre = 0.5 * (r.westRadians + r.eastRadians);
    const double west = std::max(nearLongitude(lon, centre) - dLon, r.westRadians);
    const double east = std::min(nearLongitude(lon, centre) + dLon, r.eastRadians);
    const double s = std::max(south, r.southRadians), n = std::min(north, r.northRadians);
    if (!(west <= east && s <= n)) continue;
    const auto consider = [&](const std::array<glm::dvec3, 3>& t) {
      ++nearest.trianglesTested;
      const glm::dvec3 closest = closestToOrigin(t[0], t[1], t[2]);
      const double distance = glm::length(closest);
      if (!(distance < nearest.distanceMeters)) return;
      nearest.distanceMeters = distance;
      nearest.awayEcef = distance > 0 ? -closest / distance : glm::dvec3(0.0);
      found = true;
    };
    if (tile->block->tin) {  // its own triangles near the footprint (terrain/tin_tile.hpp)
      const terrain::TinTile& tin = *tile->block->tin;
      const double width = r.eastRadians - r.westRadians, height = r.northRadians - r.southRadians;
      tin.forEachTriangleNear(
          (west - r.westRadians) / width, (s - r.southRadians) / height,
          (east - r.westRadians) / width, (n - r.southRadians) / height,
          [&](uint32_t t) { consider(tin.triangleEcefMeters(ellipsoid, t, eyeEcefMeters)); });
      continue;
    }
    const GridLocation northWest = locateInGrid(*tile, west, n);
    const GridLocation southEast = locateInGrid(*tile, east, s);
    const terrain::HeightBlock& block = *tile->block;
    const terrain::BlockGrid grid{tile->id, block.verticesPerSide};
    const uint32_t cells = block.verticesPerSide - 1;
    const uint32_t row0 = northWest.quadRow, column0 = northWest.quadColumn;
    const uint32_t row1 = std::min(southEast.quadRow, cells - 1);
    const uint32_t column1 = std::min(southEast.quadColumn, cells - 1);
    const auto vertex = [&](uint32_t row, uint32_t column) {
      return terrain::tileVertexEcefMeters(ellipsoid, grid, row, column,
                                           block.surfaceHeightMetersAt(row, column)) -
             eyeEcefMeters;
    };
    for (uint32_t i = row0; i <= row1; ++i) {
      for (uint32_t j = column0; j <= column1; ++j) {
        // The quad's two triangles by the diagonal rule (tile_mesh.hpp): SW {(i,j), (i+1,j),
        // (i+1,j+1)} and NE {(i,j), (i+1,j+1), (i,j+1)}.
        const glm::dvec3 nw = vertex(i, j), sw = vertex(i + 1, j), se = vertex(i + 1, j + 1),
                         ne = vertex(i, j + 1);
        consider({nw, sw, se});
        consider({nw, se, ne});
      }
    }
  }
  if (!found) return std::nullopt;
  if (nearest.awayEcef == glm::dvec3(0.0)) {  // on the surface: away is up
    nearest.awayEcef = geo::geodeticSurfaceNormal(ellipsoid, *eye);
  }
  return nearest;
}

LateralPush pushAwayFromTerrain(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                                const glm::dvec3& eyeEcefMeters, double radiusMeters) {
  LateralPush push;
  if (!std::isfinite(eyeEcefMeters.x + eyeEcefMeters.y + eyeEcefMeters.z) || !(radiusMeters > 0) ||
      !std::isfinite(radiusMeters)) {
    return push;
  }
  glm::dvec3 eye = eyeEcefMeters;
  for (int k = 0; k < kMaximumClearancePushes; ++k) {
    const auto nearest = nearestDrawnTriangle(array, ellipsoid, eye, radiusMeters);
    if (!nearest) break;
    push.trianglesTested += nearest->trianglesTested;
    eye +=
        (radiusMeters - nearest->distanceMeters + kClearancePushMarginMeters) * nearest->awayEcef;
  }
  push.valid = true;
  push.eyeEcefMeters = eye;
  push.pushMeters = glm::distance(eye, eyeEcefMeters);
  return push;
}

}  // namespace globe::collision
