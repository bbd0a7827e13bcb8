// The rendered triangle under a point and the height of its plane along the geodetic normal.
#include "collision/exact_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "collision/grid_location.hpp"
#include "collision/mesh_vertex_cache.hpp"
#include "collision/terrain_array.hpp"
#include "geo/ecef.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"

namespace globe::collision {
namespace {

// Planes within ~1e-6 rad of containing the normal are treated as degenerate.
constexpr double kMinimumNormalCosine = 1e-6;
// A hit this far outside a triangle (in barycentric terms) still counts as inside.
constexpr double kBarycentricTolerance = 1e-9;
constexpr int kMaximumSteps = 4;

struct Triangle {
  uint32_t row;  // quad (row, column)
  uint32_t column;
  bool southWest;
};

// Where the normal line meets the triangle's plane: the height along it and the barycentric
// coordinates of the meeting point (vertex order as in corners()).
struct PlaneHit {
  double heightMeters;
  std::array<double, 3> barycentric;
  double minimumBarycentric() const {
    return std::min({barycentric[0], barycentric[1], barycentric[2]});
  }
};

// SW: A (i,j), B (i+1,j), C (i+1,j+1); NE: A (i,j), C (i+1,j+1), D (i,j+1).
std::array<std::array<uint32_t, 2>, 3> corners(const Triangle& t) {
  const uint32_t i = t.row, j = t.column;
  if (t.southWest) return {{{i, j}, {i + 1, j}, {i + 1, j + 1}}};
  return {{{i, j}, {i + 1, j + 1}, {i, j + 1}}};
}

// The triangle sharing the edge opposite corner k, if it lies in the tile.
std::optional<Triangle> across(const Triangle& t, size_t k, uint32_t cells) {
  const uint32_t i = t.row, j = t.column;
  if (t.southWest) {
    if (k == 0) return i + 1 < cells ? std::optional<Triangle>({i + 1, j, false}) : std::nullopt;
    if (k == 1) return Triangle{i, j, false};  // the diagonal
    return j > 0 ? std::optional<Triangle>({i, j - 1, false}) : std::nullopt;
  }
  if (k == 0) return j + 1 < cells ? std::optional<Triangle>({i, j + 1, true}) : std::nullopt;
  if (k == 1) return i > 0 ? std::optional<Triangle>({i - 1, j, true}) : std::nullopt;
  return Triangle{i, j, true};  // the diagonal
}

// nullopt when the triangle is degenerate or (nearly) parallel to the normal.
std::optional<PlaneHit> meetPlane(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid,
                                  const Triangle& triangle, const glm::dvec3& surface,
                                  const glm::dvec3& normal) {
  const terrain::BlockGrid grid{tile.id, tile.block->verticesPerSide};
  std::array<glm::dvec3, 3> p{};
  const auto vertices = corners(triangle);
  for (size_t k = 0; k < 3; ++k) {
    const uint32_t row = vertices[k][0], column = vertices[k][1];
    const double h = tile.block->surfaceHeightMetersAt(row, column);
    // Relative to the surface point: the differences are small, so little is lost to rounding.
    p[k] = cachedTileVertexEcefMeters(ellipsoid, grid, row, column, h) - surface;
  }
  const glm::dvec3 planeNormal = glm::cross(p[1] - p[0], p[2] - p[0]);
  const double lengthSquared = glm::dot(planeNormal, planeNormal);
  const double along = glm::dot(planeNormal, normal);
  if (!(lengthSquared > 0.0) ||
      !(std::abs(along) > kMinimumNormalCosine * std::sqrt(lengthSquared))) {
    return std::nullopt;
  }
  PlaneHit hit{};
  hit.heightMeters = glm::dot(planeNormal, p[0]) / along;
  const glm::dvec3 x = hit.heightMeters * normal;
  for (size_t k = 0; k < 3; ++k) {
    const glm::dvec3 a = p[(k + 1) % 3] - x, b = p[(k + 2) % 3] - x;
    hit.barycentric[k] = glm::dot(planeNormal, glm::cross(a, b)) / lengthSquared;
  }
  return hit;
}

}  // namespace

SurfaceSample exactTileSurfaceHeight(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid,
                                     double longitudeRadians, double latitudeRadians) {
  if (!hasReadableBlock(tile)) return {};
  const terrain::HeightBlock& block = *tile.block;
  const uint32_t cells = block.verticesPerSide - 1;
  const GridLocation at = locateInGrid(tile, longitudeRadians, latitudeRadians);
  if (at.atPole) {
    double highest = block.surfaceHeightMetersAt(at.poleRow, 0);
    for (uint32_t column = 1; column <= cells; ++column) {
      highest = std::max(highest, block.surfaceHeightMetersAt(at.poleRow, column));
    }
    return {highest, SurfaceTriangle::Pole, at.poleRow == 0 ? 0 : cells - 1, 0};
  }
  const uint32_t i = at.quadRow;
  const uint32_t j = at.quadColumn;
  // One set of sines and cosines for both (bit for bit cartographicToEcef's and
  // geodeticSurfaceNormal's).
  const SurfacePoint nadir = surfacePointAndNormal(ellipsoid, longitudeRadians, latitudeRadians);
  const glm::dvec3& surface = nadir.pointEcefMeters;
  const glm::dvec3& normal = nadir.normal;

  Triangle current{i, j, at.row - i >= at.column - j};
  std::optional<PlaneHit> hit = meetPlane(tile, ellipsoid, current, surface, normal);
  if (!hit) {
    current.southWest = !current.southWest;
    hit = meetPlane(tile, ellipsoid, current, surface, normal);
  }
  if (!hit) {
    const double highest = std::max(
        {block.surfaceHeightMetersAt(i, j), block.surfaceHeightMetersAt(i, j + 1),
         block.surfaceHeightMetersAt(i + 1, j), block.surfaceHeightMetersAt(i + 1, j + 1)});
    return {highest, SurfaceTriangle::QuadMaximum, i, j};
  }
  // Step towards the triangle that contains the meeting point.
  for (int step = 0; step < kMaximumSteps; ++step) {
    const auto& b = hit->barycentric;
    const size_t outside = static_cast<size_t>(std::min_element(b.begin(), b.end()) - b.begin());
    if (b[outside] >= -kBarycentricTolerance) break;
    const std::optional<Triangle> next = across(current, outside, cells);
    if (!next) break;
    const std::optional<PlaneHit> nextHit = meetPlane(tile, ellipsoid, *next, surface, normal);
    if (!nextHit || nextHit->minimumBarycentric() <= hit->minimumBarycentric()) break;
    current = *next;
    hit = nextHit;
  }
  return {hit->heightMeters,
          current.southWest ? SurfaceTriangle::SouthWest : SurfaceTriangle::NorthEast, current.row,
          current.column};
}

std::optional<ExactSurfaceSample> exactSurfaceHeight(const RenderingTileArray& array,
                                                     const geo::Ellipsoid& ellipsoid,
                                                     double longitudeRadians,
                                                     double latitudeRadians) {
  const std::optional<QueryPoint> point = makeQueryPoint(longitudeRadians, latitudeRadians);
  if (!point) return std::nullopt;
  const ArrayTile* tile = array.findIndexed(point->longitudeRadians, point->latitudeRadians);
  if (tile == nullptr) return std::nullopt;
  const SurfaceSample sample =
      exactTileSurfaceHeight(*tile, ellipsoid, point->longitudeRadians, point->latitudeRadians);
  return ExactSurfaceSample{sample.heightMeters, sample.triangle, tile->id};
}

ExactSurfaceResult exactSurfaceTest(const RenderingTileArray& array,
                                    const geo::Ellipsoid& ellipsoid,
                                    const glm::dvec3& cameraEcefMeters, double clearanceMeters) {
  const std::optional<geo::Cartographic> camera =
      geo::ecefToCartographic(ellipsoid, cameraEcefMeters);
  if (!camera) return {};
  const double clearance = std::isfinite(clearanceMeters) ? clearanceMeters : 0.0;
  ExactSurfaceResult result;
  result.valid = true;
  result.cameraHeightMeters = camera->heightMeters;
  if (auto sample =
          exactSurfaceHeight(array, ellipsoid, camera->longitudeRadians, camera->latitudeRadians)) {
    result.found = true;
    result.surfaceHeightMeters = sample->heightMeters;
    result.tile = sample->tile;
    result.triangle = sample->triangle;
  }
  result.collided = result.cameraHeightMeters <= result.surfaceHeightMeters + clearance;
  return result;
}

}  // namespace globe::collision
