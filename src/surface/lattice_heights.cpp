// A lattice's nodes share their rows' latitudes and their columns' longitudes, and runs of them
// share a block: the nadir's sines and cosines are worked out per row and column, and the block
// per tile of the search's deepest level that a run of nodes lies in (nested tiling: the nodes
// of one such tile find the same finest tile), its vertices once (block_vertices.hpp).
#include "surface/lattice_heights.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_map>

#include <glm/vec3.hpp>

#include "collision/exact_surface.hpp"
#include "geo/tiling_scheme.hpp"
#include "surface/block_vertices.hpp"

namespace globe::surface {
namespace {

struct ColumnNode {
  double longitudeRadians, cosLon, sinLon;
  uint32_t tileX;  // of the search's deepest level
};
struct RowNode {
  double latitudeRadians, sinLat, cosLat, rhoMeters, zMeters;  // the nadir's, at height 0
  uint32_t tileY;
};

// The blocks a lattice's nodes read, each prepared once: keyed by the tile found.
class PreparedBlocks {
 public:
  PreparedBlocks(PyramidSurface& surface, uint32_t level) : surface_(surface), level_(level) {}

  Result<const BlockVertices*> at(double longitudeRadians, double latitudeRadians) {
    auto found = surface_.finestTile(longitudeRadians, latitudeRadians, level_);
    if (!found) return Error{found.error()};
    if (!found->block) return &none_;
    const geo::TileId id = found->arrayTile.id;
    auto [it, added] = blocks_.try_emplace(id);
    if (added) it->second = prepareBlockVertices(std::move(*found), surface_.ellipsoid());
    return &it->second;
  }

 private:
  PyramidSurface& surface_;
  uint32_t level_;
  BlockVertices none_;
  std::unordered_map<geo::TileId, BlockVertices> blocks_;
};

// geo::cartographicToEcef and geodeticSurfaceNormal at height 0, as
// collision::surfacePointAndNormal writes them, from the row's and column's terms.
double nodeHeightMeters(const BlockVertices& block, const geo::Ellipsoid& ellipsoid,
                        const RowNode& row, const ColumnNode& column) {
  if (!block.tile.block) return 0.0;
  const glm::dvec3 nadir{row.rhoMeters * column.cosLon, row.rhoMeters * column.sinLon, row.zMeters};
  const glm::dvec3 normal{row.cosLat * column.cosLon, row.cosLat * column.sinLon, row.sinLat};
  if (auto h = gridPlaneHeightMeters(block, column.longitudeRadians, row.latitudeRadians, nadir,
                                     normal)) {
    return *h;
  }
  return collision::exactTileSurfaceHeight(block.tile.arrayTile, ellipsoid, column.longitudeRadians,
                                           row.latitudeRadians)
      .heightMeters;
}

}  // namespace

Result<std::vector<double>> latticeHeightsMeters(PyramidSurface& surface,
                                                 std::span<const double> longitudesRadians,
                                                 std::span<const double> latitudesRadians,
                                                 uint32_t maxLevel) {
  using geo::GeographicTilingScheme;
  const uint32_t level = surface.deepestLevel(maxLevel);
  const geo::Ellipsoid& e = surface.ellipsoid();
  const double a = e.semiMajorAxisMeters, b = e.semiMinorAxisMeters;
  std::vector<ColumnNode> columns;
  for (const double longitude : longitudesRadians) {
    const double lon = geo::wrapLongitudeRadians(longitude);
    const auto tile = GeographicTilingScheme::positionToTile(lon, 0.0, level);
    if (!tile) return makeError("invalid position");
    columns.push_back({lon, std::cos(lon), std::sin(lon), tile->x});
  }
  std::vector<RowNode> rows;
  for (const double lat : latitudesRadians) {
    const auto tile = GeographicTilingScheme::positionToTile(0.0, lat, level);
    if (!tile) return makeError("invalid position");
    const double sinLat = std::sin(lat), cosLat = std::cos(lat);
    const double n = a / std::sqrt(1.0 - e.eccentricitySquared() * sinLat * sinLat);
    rows.push_back(
        {lat, sinLat, cosLat, (n + 0.0) * cosLat, (n * (b / a) * (b / a) + 0.0) * sinLat, tile->y});
  }
  std::vector<double> heights;
  if (columns.empty() || rows.empty()) return heights;
  heights.reserve(columns.size() * rows.size());
  const auto [westmost, eastmost] = std::minmax_element(
      columns.begin(), columns.end(), [](auto& l, auto& r) { return l.tileX < r.tileX; });
  const uint32_t firstX = westmost->tileX;
  // The block of each deepest-level tile along the current row of them (null: not looked up).
  std::vector<const BlockVertices*> run(eastmost->tileX - firstX + 1);
  uint32_t runY = std::numeric_limits<uint32_t>::max();
  PreparedBlocks blocks(surface, level);
  for (const RowNode& row : rows) {
    if (row.tileY != runY) std::fill(run.begin(), run.end(), nullptr);
    runY = row.tileY;
    for (const ColumnNode& column : columns) {
      const BlockVertices*& block = run[column.tileX - firstX];
      if (block == nullptr) {
        auto found = blocks.at(column.longitudeRadians, row.latitudeRadians);
        if (!found) return Error{found.error()};
        block = *found;
      }
      heights.push_back(nodeHeightMeters(*block, e, row, column));
    }
  }
  return heights;
}

}  // namespace globe::surface
