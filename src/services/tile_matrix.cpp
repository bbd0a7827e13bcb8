#include "services/tile_matrix.hpp"

#include <cmath>
#include <numbers>

namespace globe::services {
namespace {

constexpr double kMercatorRadiusMeters = 6378137.0;  // the sphere of EPSG:3857

}  // namespace

TileMatrixSet webMercatorQuad(uint32_t minZoom, uint32_t maxZoom, uint32_t tileSize) {
  TileMatrixSet set;
  set.crs = TileCrs::WebMercator;
  const double half = geo::kWebMercatorHalfWorldMeters;
  for (uint32_t z = minZoom; z <= maxZoom; ++z) {
    TileMatrix m;
    m.id = std::to_string(z);
    m.originX = -half;
    m.originY = half;
    m.columns = m.rows = uint64_t{1} << z;
    m.tileWidth = m.tileHeight = tileSize;
    m.unitsPerPixel = 2 * half / (static_cast<double>(m.columns) * tileSize);
    set.matrices.push_back(m);
  }
  return set;
}

TileMatrixSet geographicQuad(uint32_t minZoom, uint32_t maxZoom, uint32_t tileSize) {
  TileMatrixSet set;
  set.crs = TileCrs::Geographic;
  for (uint32_t z = minZoom; z <= maxZoom; ++z) {
    TileMatrix m;
    m.id = std::to_string(z);
    m.originX = -180;
    m.originY = 90;
    m.rows = uint64_t{1} << z;
    m.columns = 2 * m.rows;
    m.tileWidth = m.tileHeight = tileSize;
    m.unitsPerPixel = 180.0 / (static_cast<double>(m.rows) * tileSize);
    set.matrices.push_back(m);
  }
  return set;
}

std::optional<std::pair<double, double>> toCrs(TileCrs crs, double lon, double lat) {
  if (crs == TileCrs::Geographic) return std::pair{lon, lat};
  if (std::fabs(lat) > kWebMercatorMaxLatitudeDegrees + 1e-9) return std::nullopt;
  return std::pair{geo::webMercatorXMeters(lon), geo::webMercatorYMeters(lat)};
}

double crsUnitsPerDegree(TileCrs crs, double lat) {
  if (crs == TileCrs::Geographic) return 1.0;
  const double clamped = std::min(std::fabs(lat), kWebMercatorMaxLatitudeDegrees);
  return std::numbers::pi / 180 * kMercatorRadiusMeters /
         std::cos(clamped * std::numbers::pi / 180);
}

size_t matrixFor(const TileMatrixSet& set, double unitsPerPixel) {
  for (size_t i = 0; i < set.matrices.size(); ++i)
    if (set.matrices[i].unitsPerPixel <= unitsPerPixel * 1.0001) return i;
  return set.matrices.empty() ? 0 : set.matrices.size() - 1;
}

}  // namespace globe::services
