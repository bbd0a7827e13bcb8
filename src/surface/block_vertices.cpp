// The plane step of collision/exact_surface.cpp (surfaceAlongNormal's first meetPlane) on
// vertices computed once per block instead of four per point: the same operations in the same
// order, so the same doubles come out; every other case is left to the exact surface itself.
#include "surface/block_vertices.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "collision/exact_surface.hpp"
#include "collision/mesh_vertex_cache.hpp"
#include "terrain/tile_containment.hpp"

namespace globe::surface {

BlockVertices prepareBlockVertices(PyramidSurface::Loaded tile, const geo::Ellipsoid& ellipsoid) {
  BlockVertices prepared{std::move(tile), {}};
  const terrain::ArrayTile& arrayTile = prepared.tile.arrayTile;
  constexpr double kHalfPi = std::numbers::pi / 2;
  // A pole row's points take the highest of its vertices, a TIN its own triangles: both are
  // collision's to answer.
  if (!terrain::hasReadableBlock(arrayTile) || arrayTile.block->tin ||
      arrayTile.northRadians >= kHalfPi || arrayTile.southRadians <= -kHalfPi) {
    return prepared;
  }
  prepared.ecefMeters = collision::blockVertexEcefMeters(
      ellipsoid, {arrayTile.id, arrayTile.block->verticesPerSide}, *arrayTile.block);
  prepared.cells = static_cast<double>(arrayTile.block->verticesPerSide - 1);
  prepared.columnsPerRadian = prepared.cells / (arrayTile.eastRadians - arrayTile.westRadians);
  prepared.rowsPerRadian = prepared.cells / (arrayTile.northRadians - arrayTile.southRadians);
  return prepared;
}

namespace {

// collision::locateInGrid's continuous coordinate and quad along one axis (the snapping to grid
// lines aside, which the plane step does not read), with the tile's terms from BlockVertices.
struct AxisPlace {
  double coordinate;
  uint32_t cell;
};
AxisPlace placeOnAxis(double coordinate, double cells) {
  const double clamped = std::isfinite(coordinate) ? std::clamp(coordinate, 0.0, cells) : 0.0;
  return {clamped, std::min(static_cast<uint32_t>(clamped), static_cast<uint32_t>(cells) - 1)};
}

}  // namespace

std::optional<double> gridPlaneHeightMeters(const BlockVertices& block, double longitudeRadians,
                                            double latitudeRadians,
                                            const glm::dvec3& nadirEcefMeters,
                                            const glm::dvec3& normal) {
  if (block.ecefMeters.empty()) return std::nullopt;
  const terrain::ArrayTile& tile = block.tile.arrayTile;
  const double longitude = terrain::longitudeInTile(tile, longitudeRadians);
  const AxisPlace column =
      placeOnAxis((longitude - tile.westRadians) * block.columnsPerRadian, block.cells);
  const AxisPlace row =
      placeOnAxis((tile.northRadians - latitudeRadians) * block.rowsPerRadian, block.cells);
  const uint32_t n = tile.block->verticesPerSide, i = row.cell, j = column.cell;
  const auto vertex = [&](uint32_t r, uint32_t c) {
    return block.ecefMeters[size_t{r} * n + c] - nadirEcefMeters;
  };
  // The diagonal rule: south-west {(i,j), (i+1,j), (i+1,j+1)}, north-east {(i,j), (i+1,j+1),
  // (i,j+1)}, the diagonal itself to the south-west.
  const bool southWest = row.coordinate - i >= column.coordinate - j;
  const std::array<glm::dvec3, 3> p{vertex(i, j),
                                    southWest ? vertex(i + 1, j) : vertex(i + 1, j + 1),
                                    southWest ? vertex(i + 1, j + 1) : vertex(i, j + 1)};
  const glm::dvec3 planeNormal = glm::cross(p[1] - p[0], p[2] - p[0]);
  const double lengthSquared = glm::dot(planeNormal, planeNormal);
  const double along = glm::dot(planeNormal, normal);
  constexpr double kCosine = collision::kMinimumNormalCosine;
  if (!(lengthSquared > 0.0) || !(along * along > kCosine * kCosine * lengthSquared)) {
    return std::nullopt;  // degenerate: collision takes the quad's other half
  }
  const double heightMeters = glm::dot(planeNormal, p[0]) / along;
  const glm::dvec3 x = heightMeters * normal;
  const double inverseLengthSquared = 1.0 / lengthSquared;
  for (size_t k = 0; k < 3; ++k) {
    const glm::dvec3 a = p[(k + 1) % 3] - x, b = p[(k + 2) % 3] - x;
    // Outside by more than the tolerance: collision steps to the triangle the ray really hits.
    if (glm::dot(planeNormal, glm::cross(a, b)) * inverseLengthSquared <
        -collision::kBarycentricTolerance) {
      return std::nullopt;
    }
  }
  return heightMeters;
}

}  // namespace globe::surface
