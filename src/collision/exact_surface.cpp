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
#include "terrain/tin_tile.hpp"

namespace globe::collision {
namespace {

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

// Where a tile's vertices lie: the mesh's own positions (terrain::BlockGrid), bit for bit.
struct TileVertexPlacement {
  const ArrayTile& tile;
  const geo::Ellipsoid& ellipsoid;

  glm::dvec3 ecefMeters(uint32_t row, uint32_t column) const {
    return cachedTileVertexEcefMeters(ellipsoid, {tile.id, tile.block->verticesPerSide}, row,
                                      column, tile.block->surfaceHeightMetersAt(row, column));
  }
};

// The four corners of the last quad a thread queried, with everything that determines them: a
// camera stays over one quad for many frames (50 m/s at 60 Hz crosses a 60 m quad in 70), and
// then they are reused instead of recomputed.
struct QuadCorners {
  double a = 0.0, b = 0.0;
  geo::TileId tile{};
  uint32_t verticesPerSide = 0, row = 0, column = 0;
  std::array<double, 4> heightsMeters{};
  std::array<glm::dvec3, 4> ecefMeters{};
  bool valid = false;
};

const QuadCorners& quadCorners(const TileVertexPlacement& placement, uint32_t row,
                               uint32_t column) {
  thread_local QuadCorners last;
  const terrain::HeightBlock& block = *placement.tile.block;
  const std::array<double, 4> heights{block.surfaceHeightMetersAt(row, column),
                                      block.surfaceHeightMetersAt(row, column + 1),
                                      block.surfaceHeightMetersAt(row + 1, column),
                                      block.surfaceHeightMetersAt(row + 1, column + 1)};
  const geo::Ellipsoid& e = placement.ellipsoid;
  if (last.valid && last.a == e.semiMajorAxisMeters && last.b == e.semiMinorAxisMeters &&
      last.tile == placement.tile.id && last.verticesPerSide == block.verticesPerSide &&
      last.row == row && last.column == column && last.heightsMeters == heights) {
    return last;
  }
  last = {e.semiMajorAxisMeters,
          e.semiMinorAxisMeters,
          placement.tile.id,
          block.verticesPerSide,
          row,
          column,
          heights,
          {},
          true};
  for (uint32_t corner = 0; corner < 4; ++corner) {
    last.ecefMeters[corner] = placement.ecefMeters(row + corner / 2, column + corner % 2);
  }
  return last;
}

// The tile's vertices relative to the nadir point: the quad under it from QuadCorners, its
// neighbours (where the stepping below goes, rarely) computed.
class RelativeVertices {
 public:
  RelativeVertices(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid,
                   const glm::dvec3& surface, uint32_t quadRow, uint32_t quadColumn)
      : placement_{tile, ellipsoid},
        surface_(surface),
        quadRow_(quadRow),
        quadColumn_(quadColumn),
        corners_(quadCorners(placement_, quadRow, quadColumn).ecefMeters) {}

  glm::dvec3 at(uint32_t row, uint32_t column) const {
    const uint32_t dr = row - quadRow_, dc = column - quadColumn_;
    // Relative to the surface point: the differences are small, so little is lost to rounding.
    if (dr > 1 || dc > 1) return placement_.ecefMeters(row, column) - surface_;  // unsigned wrap
    return corners_[dr * 2 + dc] - surface_;
  }

 private:
  TileVertexPlacement placement_;
  glm::dvec3 surface_;
  uint32_t quadRow_, quadColumn_;
  std::array<glm::dvec3, 4> corners_;
};

// nullopt when the triangle is degenerate or (nearly) parallel to the normal.
std::optional<PlaneHit> meetPlane(const RelativeVertices& vertices, const Triangle& triangle,
                                  const glm::dvec3& normal) {
  std::array<glm::dvec3, 3> p{};
  const auto corner = corners(triangle);
  for (size_t k = 0; k < 3; ++k) p[k] = vertices.at(corner[k][0], corner[k][1]);
  const glm::dvec3 planeNormal = glm::cross(p[1] - p[0], p[2] - p[0]);
  const double lengthSquared = glm::dot(planeNormal, planeNormal);
  const double along = glm::dot(planeNormal, normal);
  // |along| > cos * |planeNormal|, squared (no square root).
  if (!(lengthSquared > 0.0) ||
      !(along * along > kMinimumNormalCosine * kMinimumNormalCosine * lengthSquared)) {
    return std::nullopt;
  }
  PlaneHit hit{};
  hit.heightMeters = glm::dot(planeNormal, p[0]) / along;
  const glm::dvec3 x = hit.heightMeters * normal;
  const double inverseLengthSquared = 1.0 / lengthSquared;
  for (size_t k = 0; k < 3; ++k) {
    const glm::dvec3 a = p[(k + 1) % 3] - x, b = p[(k + 2) % 3] - x;
    hit.barycentric[k] = glm::dot(planeNormal, glm::cross(a, b)) * inverseLengthSquared;
  }
  return hit;
}

}  // namespace

namespace {

// The drawn surface's height along the normal line through surface (the nadir point on the
// ellipsoid) for a point located in the tile's grid.
SurfaceSample surfaceAlongNormal(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid,
                                 const GridLocation& at, const glm::dvec3& surface,
                                 const glm::dvec3& normal) {
  const terrain::HeightBlock& block = *tile.block;
  const uint32_t cells = block.verticesPerSide - 1;
  const uint32_t i = at.quadRow;
  const uint32_t j = at.quadColumn;
  RelativeVertices vertices(tile, ellipsoid, surface, i, j);
  Triangle current{i, j, at.row - i >= at.column - j};
  std::optional<PlaneHit> hit = meetPlane(vertices, current, normal);
  if (!hit) {
    current.southWest = !current.southWest;
    hit = meetPlane(vertices, current, normal);
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
    const std::optional<PlaneHit> nextHit = meetPlane(vertices, *next, normal);
    if (!nextHit || nextHit->minimumBarycentric() <= hit->minimumBarycentric()) break;
    current = *next;
    hit = nextHit;
  }
  return {hit->heightMeters,
          current.southWest ? SurfaceTriangle::SouthWest : SurfaceTriangle::NorthEast, current.row,
          current.column};
}

// On a pole row every vertex is the pole: the highest of them.
SurfaceSample poleSurface(const terrain::HeightBlock& block, const GridLocation& at) {
  const uint32_t cells = block.verticesPerSide - 1;
  double highest = block.surfaceHeightMetersAt(at.poleRow, 0);
  for (uint32_t column = 1; column <= cells; ++column) {
    highest = std::max(highest, block.surfaceHeightMetersAt(at.poleRow, column));
  }
  return {highest, SurfaceTriangle::Pole, at.poleRow == 0 ? 0 : cells - 1, 0};
}

// A TIN tile's drawn triangle under the nadir (terrain/tin_tile.hpp finds it in O(1)) and its
// plane's height along the normal. Its vertices are where the mesh draws them, so the height is
// the drawn surface's (as the grid's); a triangle (nearly) parallel to the normal gives its
// highest vertex. nullopt when no triangle lies under the point.
std::optional<SurfaceSample> tinSurfaceAlongNormal(const ArrayTile& tile,
                                                   const geo::Ellipsoid& ellipsoid,
                                                   double longitudeRadians, double latitudeRadians,
                                                   const glm::dvec3& surface,
                                                   const glm::dvec3& normal) {
  const terrain::TinTile& tin = *tile.block->tin;
  const terrain::TinHeight at = tin.heightAt(longitudeRadians, latitudeRadians);
  if (!at.found) return std::nullopt;
  const std::array<glm::dvec3, 3> p = tin.triangleEcefMeters(ellipsoid, at.triangle, surface);
  const glm::dvec3 planeNormal = glm::cross(p[1] - p[0], p[2] - p[0]);
  const double lengthSquared = glm::dot(planeNormal, planeNormal);
  const double along = glm::dot(planeNormal, normal);
  if (!(lengthSquared > 0.0) ||
      !(along * along > kMinimumNormalCosine * kMinimumNormalCosine * lengthSquared)) {
    return SurfaceSample{at.conservativeMeters, SurfaceTriangle::Tin, at.triangle, 0};
  }
  return SurfaceSample{glm::dot(planeNormal, p[0]) / along, SurfaceTriangle::Tin, at.triangle, 0};
}

// The drawn surface along the normal through the nadir point `surface`: a TIN tile's triangle,
// else (or where its TIN leaves the point open) the grid's.
SurfaceSample surfaceAt(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid,
                        double longitudeRadians, double latitudeRadians, const glm::dvec3& surface,
                        const glm::dvec3& normal) {
  if (tile.block->tin) {
    if (auto hit = tinSurfaceAlongNormal(tile, ellipsoid, longitudeRadians, latitudeRadians,
                                         surface, normal)) {
      return *hit;
    }
  }
  const GridLocation at = locateInGrid(tile, longitudeRadians, latitudeRadians);
  if (at.atPole) return poleSurface(*tile.block, at);
  return surfaceAlongNormal(tile, ellipsoid, at, surface, normal);
}

}  // namespace

SurfaceSample exactTileSurfaceHeight(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid,
                                     double longitudeRadians, double latitudeRadians) {
  if (!hasReadableBlock(tile)) return {};
  // One set of sines and cosines for both (bit for bit cartographicToEcef's and
  // geodeticSurfaceNormal's).
  const SurfacePoint nadir = surfacePointAndNormal(ellipsoid, longitudeRadians, latitudeRadians);
  return surfaceAt(tile, ellipsoid, longitudeRadians, latitudeRadians, nadir.pointEcefMeters,
                   nadir.normal);
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
  // The conversion's own normal: the camera lies on the normal line through its nadir, so the
  // nadir point is the camera moved D down it, and no sines or cosines are needed.
  const std::optional<geo::GeodeticFrame> frame =
      geo::ecefToGeodeticFrame(ellipsoid, cameraEcefMeters);
  if (!frame) return {};
  const geo::Cartographic& camera = frame->cartographic;
  const double clearance = std::isfinite(clearanceMeters) ? clearanceMeters : 0.0;
  ExactSurfaceResult result;
  result.valid = true;
  result.cameraHeightMeters = camera.heightMeters;
  const std::optional<QueryPoint> point =
      makeQueryPoint(camera.longitudeRadians, camera.latitudeRadians);
  const ArrayTile* tile = point ? array.lookupIndexed(*point).tile : nullptr;
  if (tile != nullptr && hasReadableBlock(*tile)) {
    const SurfaceSample sample =
        surfaceAt(*tile, ellipsoid, point->longitudeRadians, point->latitudeRadians,
                  cameraEcefMeters - camera.heightMeters * frame->normal, frame->normal);
    result.found = true;
    result.surfaceHeightMeters = sample.heightMeters;
    result.tile = tile->id;
    result.triangle = sample.triangle;
  }
  result.collided = result.cameraHeightMeters <= result.surfaceHeightMeters + clearance;
  return result;
}

}  // namespace globe::collision
