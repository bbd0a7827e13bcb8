#include "publish/tile_grid.hpp"

#include <glm/geometric.hpp>
#include <numbers>

#include "geo/ecef.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"

namespace globe::publish {
namespace {

constexpr double kGridRadiansPerDegree = std::numbers::pi / 180;

glm::dvec3 apronPositionEcefMeters(const TileGrid& grid, const geo::Ellipsoid& ellipsoid, int row,
                                   int column) {
  const terrain::BlockGrid blockGrid{grid.tile, grid.side};
  const auto vertex = blockGrid.wrappedVertex(row, column);
  return geo::cartographicToEcef(
      ellipsoid, {vertex.longitudeDegrees * kGridRadiansPerDegree,
                  vertex.latitudeDegrees * kGridRadiansPerDegree, grid.apronAt(row, column)});
}

}  // namespace

Result<TileGrid> sampleTileGrid(surface::PyramidSurface& surface, const geo::TileId& tile, uint32_t side,
                                uint32_t maxLevel) {
  TileGrid grid{tile, side, {}, {}};
  const terrain::BlockGrid blockGrid{tile, side};
  const int n = static_cast<int>(side);
  grid.apronMeters.reserve(static_cast<size_t>(n + 2) * (n + 2));
  grid.heightsMeters.reserve(static_cast<size_t>(n) * n);
  for (int row = -1; row <= n; ++row) {
    for (int column = -1; column <= n; ++column) {
      const auto vertex = blockGrid.wrappedVertex(row, column);
      auto h = surface.heightMeters(vertex.longitudeDegrees * kGridRadiansPerDegree,
                                    vertex.latitudeDegrees * kGridRadiansPerDegree, maxLevel);
      if (!h) return Error{h.error()};
      grid.apronMeters.push_back(*h);
      if (row >= 0 && row < n && column >= 0 && column < n) grid.heightsMeters.push_back(*h);
    }
  }
  return grid;
}

std::vector<std::array<double, 3>> gridPositionsEcefMeters(const TileGrid& grid,
                                                           const geo::Ellipsoid& ellipsoid) {
  const terrain::BlockGrid blockGrid{grid.tile, grid.side};
  std::vector<std::array<double, 3>> positions;
  positions.reserve(grid.heightsMeters.size());
  for (uint32_t row = 0; row < grid.side; ++row) {
    for (uint32_t column = 0; column < grid.side; ++column) {
      const glm::dvec3 p = terrain::tileVertexEcefMeters(
          ellipsoid, blockGrid, row, column, grid.heightsMeters[size_t{row} * grid.side + column]);
      positions.push_back({p.x, p.y, p.z});
    }
  }
  return positions;
}

std::array<float, 3> gridNormal(const TileGrid& grid, const geo::Ellipsoid& ellipsoid, int row,
                                int column) {
  const glm::dvec3 east = apronPositionEcefMeters(grid, ellipsoid, row, column + 1) -
                          apronPositionEcefMeters(grid, ellipsoid, row, column - 1);
  const glm::dvec3 north = apronPositionEcefMeters(grid, ellipsoid, row - 1, column) -
                           apronPositionEcefMeters(grid, ellipsoid, row + 1, column);
  glm::dvec3 normal = glm::cross(east, north);
  const double length = glm::length(normal);
  if (!(length > 1e-9 * glm::dot(east, east) + 1e-12)) {
    normal = geo::geodeticSurfaceNormal(ellipsoid,
                                        apronPositionEcefMeters(grid, ellipsoid, row, column));
  } else {
    normal /= length;
  }
  return {static_cast<float>(normal.x), static_cast<float>(normal.y), static_cast<float>(normal.z)};
}

}  // namespace globe::publish
