#include "publish/block_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <utility>
#include <vector>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"

namespace globe::publish {
namespace {

// Cesium's horizon-culling point for these positions (EllipsoidalOccluder): on the ray through
// the scaled centre, far enough out that a viewer who cannot see it cannot see the tile.
std::array<double, 3> horizonOcclusionPoint(const std::vector<glm::dvec3>& positionsEcefMeters,
                                            const glm::dvec3& centerEcefMeters,
                                            const geo::Ellipsoid& ellipsoid) {
  const glm::dvec3 radii(ellipsoid.semiMajorAxisMeters, ellipsoid.semiMajorAxisMeters,
                         ellipsoid.semiMinorAxisMeters);
  const glm::dvec3 direction = glm::normalize(centerEcefMeters / radii);
  double magnitude = 0;
  for (const glm::dvec3& position : positionsEcefMeters) {
    const glm::dvec3 scaled = position / radii;
    const double squared = std::max(1.0, glm::dot(scaled, scaled));
    const double length = std::max(1.0, std::sqrt(squared));
    const glm::dvec3 unit = glm::normalize(scaled);
    const double cosAlpha = glm::dot(unit, direction);
    const double sinAlpha = glm::length(glm::cross(unit, direction));
    const double cosBeta = 1.0 / length;
    const double sinBeta = std::sqrt(squared - 1.0) * cosBeta;
    const double denominator = cosAlpha * cosBeta - sinAlpha * sinBeta;
    // A tile wider than a hemisphere has no such point: the centre's ray at the surface then.
    magnitude = std::max(magnitude, denominator > 0 ? 1.0 / denominator : 1.0);
  }
  const glm::dvec3 point = direction * std::max(magnitude, 1.0);
  return {point.x, point.y, point.z};
}

}  // namespace

GridTin wholeGridTin(uint32_t n) {
  GridTin tin;
  for (uint32_t i = 0; i < n * n; ++i) tin.samples.push_back(i);
  const auto at = [n](uint32_t row, uint32_t column) { return row * n + column; };
  for (uint32_t i = 0; i + 1 < n; ++i) {
    for (uint32_t j = 0; j + 1 < n; ++j) {
      tin.triangles.insert(tin.triangles.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      tin.triangles.insert(tin.triangles.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return tin;
}

BlockMesh quantizedMeshOfGrid(const geo::TileId& tile, uint32_t verticesPerSide,
                              const std::vector<double>& heightsMeters,
                              const geo::Ellipsoid& ellipsoid) {
  return quantizedMeshOfTin(tile, verticesPerSide, heightsMeters, wholeGridTin(verticesPerSide),
                            ellipsoid);
}

BlockMesh quantizedMeshOfTin(const geo::TileId& tile, uint32_t verticesPerSide,
                             const std::vector<double>& heightsMeters, const GridTin& tin,
                             const geo::Ellipsoid& ellipsoid) {
  const uint32_t n = verticesPerSide;
  const terrain::BlockGrid grid{tile, n};
  BlockMesh out;
  formats::QuantizedMesh& mesh = out.mesh;
  // The culling volumes from every sample: the TIN's flat triangles lie within their hull.
  std::vector<glm::dvec3> positions;
  double lowest = INFINITY;
  double highest = -INFINITY;
  for (uint32_t row = 0; row < n; ++row) {
    for (uint32_t column = 0; column < n; ++column) {
      const double h = heightsMeters[size_t{row} * n + column];
      positions.push_back(terrain::tileVertexEcefMeters(ellipsoid, grid, row, column, h));
      lowest = std::min(lowest, h);
      highest = std::max(highest, h);
    }
  }
  double lowestVertex = INFINITY;
  double highestVertex = -INFINITY;
  // Border vertices by their position along the side (u or v), for the edge lists.
  std::vector<std::pair<uint16_t, uint32_t>> west, south, east, north;
  for (uint32_t sample : tin.samples) {
    const uint32_t row = sample / n, column = sample % n;
    const double h = heightsMeters[sample];
    // u east, v north: row 0 is the north edge.
    const auto u =
        static_cast<uint16_t>(std::lround(double{formats::kQuantizedMax} * column / (n - 1)));
    const auto v = static_cast<uint16_t>(
        std::lround(double{formats::kQuantizedMax} * (n - 1 - row) / (n - 1)));
    const auto index = static_cast<uint32_t>(mesh.u.size());
    mesh.u.push_back(u);
    mesh.v.push_back(v);
    mesh.heightMeters.push_back(h);
    lowestVertex = std::min(lowestVertex, h);
    highestVertex = std::max(highestVertex, h);
    if (column == 0) west.emplace_back(v, index);
    if (column == n - 1) east.emplace_back(v, index);
    if (row == n - 1) south.emplace_back(u, index);
    if (row == 0) north.emplace_back(u, index);
  }
  mesh.minimumHeightMeters = static_cast<float>(lowestVertex);
  mesh.maximumHeightMeters = static_cast<float>(highestVertex);
  mesh.triangles = tin.triangles;
  const auto edge = [](std::vector<std::pair<uint16_t, uint32_t>>& side) {
    std::sort(side.begin(), side.end());
    std::vector<uint32_t> indices;
    for (const auto& [position, index] : side) indices.push_back(index);
    return indices;
  };
  mesh.westEdge = edge(west);  // from the south, as v grows
  mesh.eastEdge = edge(east);
  mesh.southEdge = edge(south);  // from the west, as u grows
  mesh.northEdge = edge(north);

  // The centre: the rectangle's middle at the middle height (on the tile, as readers check).
  const geo::GlobeRectangle r = geo::GeographicTilingScheme::tileRectangle(tile);
  const glm::dvec3 center = geo::cartographicToEcef(
      ellipsoid, {(r.westRadians + r.eastRadians) / 2, (r.southRadians + r.northRadians) / 2,
                  (lowest + highest) / 2});
  mesh.centerEcefMeters = {center.x, center.y, center.z};
  double radius = 0;
  for (const glm::dvec3& p : positions) radius = std::max(radius, glm::distance(p, center));
  out.culling.boundingSphereCenterEcefMeters = mesh.centerEcefMeters;
  out.culling.boundingSphereRadiusMeters = radius;
  out.culling.horizonOcclusionPointScaled = horizonOcclusionPoint(positions, center, ellipsoid);
  return out;
}

}  // namespace globe::publish
