// Möller-Trumbore against all grid triangles of a tile, in double, relative to the nadir point.
#include "tests/collision/mesh_ray_cast.hpp"

#include <array>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"

namespace globe::collision::testing {

namespace {

// The tile's vertices in ECEF, as tile_mesh builds them, for the last few tiles cast onto: the
// sines and cosines of n² vertices were most of an oracle query, and the queries of one frame
// fall on a few tiles. An entry is reused only for the same tile, ellipsoid and heights (compared
// in full), so a reused block address never returns another tile's vertices.
struct CachedVertices {
  geo::TileId id{};
  double semiMajorAxisMeters = 0, semiMinorAxisMeters = 0;
  std::vector<double> heightsMeters;
  std::vector<glm::dvec3> ecefMeters;
};

const std::vector<glm::dvec3>& tileVertices(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid) {
  constexpr size_t kEntries = 8;
  thread_local std::array<CachedVertices, kEntries> cache;
  thread_local size_t next = 0;
  const uint32_t n = tile.block->verticesPerSide;
  std::vector<double> heights(size_t{n} * n);
  for (uint32_t i = 0; i < n; ++i) {
    for (uint32_t j = 0; j < n; ++j) heights[size_t{i} * n + j] = tile.block->surfaceHeightMetersAt(i, j);
  }
  for (const CachedVertices& entry : cache) {
    if (entry.id == tile.id && entry.semiMajorAxisMeters == ellipsoid.semiMajorAxisMeters &&
        entry.semiMinorAxisMeters == ellipsoid.semiMinorAxisMeters &&
        entry.heightsMeters == heights) {
      return entry.ecefMeters;
    }
  }
  CachedVertices& entry = cache[next];
  next = (next + 1) % kEntries;
  const terrain::BlockGrid grid{tile.id, n};
  entry.ecefMeters.resize(heights.size());
  for (uint32_t i = 0; i < n; ++i) {
    for (uint32_t j = 0; j < n; ++j) {
      const size_t k = size_t{i} * n + j;
      entry.ecefMeters[k] = terrain::tileVertexEcefMeters(ellipsoid, grid, i, j, heights[k]);
    }
  }
  entry.id = tile.id;
  entry.semiMajorAxisMeters = ellipsoid.semiMajorAxisMeters;
  entry.semiMinorAxisMeters = ellipsoid.semiMinorAxisMeters;
  entry.heightsMeters = std::move(heights);
  return entry.ecefMeters;
}

}  // namespace

std::optional<MeshHit> castOntoTileMesh(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid,
                                        double longitudeRadians, double latitudeRadians) {
  const uint32_t n = tile.block->verticesPerSide;
  const geo::Cartographic nadir{longitudeRadians, latitudeRadians, 0.0};
  const glm::dvec3 surface = geo::cartographicToEcef(ellipsoid, nadir);
  const glm::dvec3 up = geo::geodeticSurfaceNormal(ellipsoid, nadir);
  constexpr double kStartMeters = 1e5;
  const glm::dvec3 origin = kStartMeters * up;  // relative to the surface point
  const glm::dvec3 direction = -up;

  const std::vector<glm::dvec3>& vertices = tileVertices(tile, ellipsoid);
  std::vector<glm::dvec3> p(vertices.size());
  for (size_t k = 0; k < p.size(); ++k) p[k] = vertices[k] - surface;
  auto at = [&](uint32_t i, uint32_t j) { return p[size_t{i} * n + j]; };
  std::optional<MeshHit> best;
  double bestT = 0.0;
  constexpr double kTolerance = 1e-9;
  for (uint32_t i = 0; i + 1 < n; ++i) {
    for (uint32_t j = 0; j + 1 < n; ++j) {
      const std::array<std::array<glm::dvec3, 3>, 2> triangles{
          {{at(i, j), at(i + 1, j), at(i + 1, j + 1)}, {at(i, j), at(i + 1, j + 1), at(i, j + 1)}}};
      for (size_t half = 0; half < 2; ++half) {
        const auto& t = triangles[half];
        const glm::dvec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
        const glm::dvec3 q = glm::cross(direction, e2);
        const double det = glm::dot(e1, q);
        if (!(std::abs(det) > 1e-12 * glm::length(e1) * glm::length(e2))) continue;
        const glm::dvec3 s = origin - t[0];
        const double u = glm::dot(s, q) / det;
        const glm::dvec3 r = glm::cross(s, e1);
        const double v = glm::dot(direction, r) / det;
        if (u < -kTolerance || v < -kTolerance || u + v > 1.0 + kTolerance) continue;
        const double distance = glm::dot(e2, r) / det;
        if (!best || distance < bestT) {
          bestT = distance;
          best = MeshHit{kStartMeters - distance, i, j, half == 0};
        }
      }
    }
  }
  return best;
}

}  // namespace globe::collision::testing
