// The formulas of geo::cartographicToEcef and terrain/tile_mesh.cpp's vertexEcef, term for term
// in the same order (tests/collision/test_mesh_vertex_cache.cpp checks them bit for bit).
#include "collision/mesh_vertex_cache.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <vector>

#include "geo/cartographic.hpp"

namespace globe::collision {
namespace {

constexpr size_t kSlots = 64;  // a query uses 2 rows and 2 columns; a flight stays on a few

struct RowTrig {
  uint64_t key = 0;  // the latitude's bits, with the ellipsoid's
  double a = 0.0, b = 0.0;
  double sinLat = 0.0, cosLat = 0.0, n = 0.0, nPolar = 0.0;  // nPolar = n (b/a)^2
  bool valid = false;
};
struct ColumnTrig {
  uint64_t key = 0;
  double cosLon = 0.0, sinLon = 0.0;
  bool valid = false;
};

size_t slotOf(uint64_t key) { return (key * 0x9E3779B97F4A7C15ULL) >> 58; }  // 6 bits

void fillRowTrig(RowTrig& row, const geo::Ellipsoid& ellipsoid, double latitudeDegrees) {
  const double a = ellipsoid.semiMajorAxisMeters, b = ellipsoid.semiMinorAxisMeters;
  const double latitude = geo::degreesToRadians(latitudeDegrees);
  row.key = std::bit_cast<uint64_t>(latitudeDegrees);
  row.a = a;
  row.b = b;
  row.sinLat = std::sin(latitude);
  row.cosLat = std::cos(latitude);
  row.n = a / std::sqrt(1.0 - ellipsoid.eccentricitySquared() * row.sinLat * row.sinLat);
  row.nPolar = row.n * (b / a) * (b / a);
  row.valid = true;
}

void fillColumnTrig(ColumnTrig& column, double longitudeDegrees) {
  const double longitude = geo::degreesToRadians(longitudeDegrees);
  column.key = std::bit_cast<uint64_t>(longitudeDegrees);
  column.cosLon = std::cos(longitude);
  column.sinLon = std::sin(longitude);
  column.valid = true;
}

const RowTrig& rowTrig(const geo::Ellipsoid& ellipsoid, double latitudeDegrees) {
  thread_local std::array<RowTrig, kSlots> rows;
  const uint64_t key = std::bit_cast<uint64_t>(latitudeDegrees);
  const double a = ellipsoid.semiMajorAxisMeters, b = ellipsoid.semiMinorAxisMeters;
  RowTrig& slot = rows[slotOf(key)];
  if (slot.valid && slot.key == key && slot.a == a && slot.b == b) return slot;
  fillRowTrig(slot, ellipsoid, latitudeDegrees);
  return slot;
}

const ColumnTrig& columnTrig(double longitudeDegrees) {
  thread_local std::array<ColumnTrig, kSlots> columns;
  const uint64_t key = std::bit_cast<uint64_t>(longitudeDegrees);
  ColumnTrig& slot = columns[slotOf(key)];
  if (slot.valid && slot.key == key) return slot;
  fillColumnTrig(slot, longitudeDegrees);
  return slot;
}

// terrain::tileVertexEcefMeters' formula on its row's and column's terms.
glm::dvec3 vertexOf(const RowTrig& r, const ColumnTrig& c, double latitudeDegrees,
                    double heightMeters) {
  const double z = (r.nPolar + heightMeters) * r.sinLat;
  if (std::abs(latitudeDegrees) == 90.0) return {0.0, 0.0, z};  // on the polar axis
  const double rho = (r.n + heightMeters) * r.cosLat;
  return {rho * c.cosLon, rho * c.sinLon, z};
}

}  // namespace

glm::dvec3 cachedTileVertexEcefMeters(const geo::Ellipsoid& ellipsoid,
                                      const terrain::BlockGrid& grid, uint32_t row, uint32_t column,
                                      double heightMeters) {
  const double latitudeDegrees = grid.latitudeDegrees(row);
  const RowTrig& r = rowTrig(ellipsoid, latitudeDegrees);
  const ColumnTrig pole{};  // a pole's vertex has no longitude
  const ColumnTrig& c =
      std::abs(latitudeDegrees) == 90.0 ? pole : columnTrig(grid.longitudeDegrees(column));
  return vertexOf(r, c, latitudeDegrees, heightMeters);
}

std::vector<glm::dvec3> blockVertexEcefMeters(const geo::Ellipsoid& ellipsoid,
                                              const terrain::BlockGrid& grid,
                                              const terrain::HeightBlock& block) {
  const uint32_t n = grid.verticesPerSide;
  std::vector<ColumnTrig> columns(n);
  for (uint32_t column = 0; column < n; ++column) {
    fillColumnTrig(columns[column], grid.longitudeDegrees(column));
  }
  std::vector<glm::dvec3> vertices;
  vertices.reserve(size_t{n} * n);
  RowTrig r;
  for (uint32_t row = 0; row < n; ++row) {
    const double latitudeDegrees = grid.latitudeDegrees(row);
    fillRowTrig(r, ellipsoid, latitudeDegrees);
    for (uint32_t column = 0; column < n; ++column) {
      vertices.push_back(
          vertexOf(r, columns[column], latitudeDegrees, block.surfaceHeightMetersAt(row, column)));
    }
  }
  return vertices;
}

SurfacePoint surfacePointAndNormal(const geo::Ellipsoid& ellipsoid, double longitudeRadians,
                                   double latitudeRadians) {
  const double a = ellipsoid.semiMajorAxisMeters, b = ellipsoid.semiMinorAxisMeters;
  const double sinLat = std::sin(latitudeRadians), cosLat = std::cos(latitudeRadians);
  const double cosLon = std::cos(longitudeRadians), sinLon = std::sin(longitudeRadians);
  const double n = a / std::sqrt(1.0 - ellipsoid.eccentricitySquared() * sinLat * sinLat);
  const double rho = (n + 0.0) * cosLat;
  return {{rho * cosLon, rho * sinLon, (n * (b / a) * (b / a) + 0.0) * sinLat},
          {cosLat * cosLon, cosLat * sinLon, sinLat}};
}

}  // namespace globe::collision
