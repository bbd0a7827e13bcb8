// The formulas of geo::cartographicToEcef and terrain/tile_mesh.cpp's vertexEcef, term for term
// in the same order (tests/collision/test_mesh_vertex_cache.cpp checks them bit for bit).
#include "collision/mesh_vertex_cache.hpp"

#include <array>
#include <bit>
#include <cmath>

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

const RowTrig& rowTrig(const geo::Ellipsoid& ellipsoid, double latitudeDegrees) {
  thread_local std::array<RowTrig, kSlots> rows;
  const uint64_t key = std::bit_cast<uint64_t>(latitudeDegrees);
  const double a = ellipsoid.semiMajorAxisMeters, b = ellipsoid.semiMinorAxisMeters;
  RowTrig& slot = rows[slotOf(key)];
  if (slot.valid && slot.key == key && slot.a == a && slot.b == b) return slot;
  const double latitude = geo::degreesToRadians(latitudeDegrees);
  slot.key = key;
  slot.a = a;
  slot.b = b;
  slot.sinLat = std::sin(latitude);
  slot.cosLat = std::cos(latitude);
  slot.n = a / std::sqrt(1.0 - ellipsoid.eccentricitySquared() * slot.sinLat * slot.sinLat);
  slot.nPolar = slot.n * (b / a) * (b / a);
  slot.valid = true;
  return slot;
}

const ColumnTrig& columnTrig(double longitudeDegrees) {
  thread_local std::array<ColumnTrig, kSlots> columns;
  const uint64_t key = std::bit_cast<uint64_t>(longitudeDegrees);
  ColumnTrig& slot = columns[slotOf(key)];
  if (slot.valid && slot.key == key) return slot;
  const double longitude = geo::degreesToRadians(longitudeDegrees);
  slot.key = key;
  slot.cosLon = std::cos(longitude);
  slot.sinLon = std::sin(longitude);
  slot.valid = true;
  return slot;
}

}  // namespace

glm::dvec3 cachedTileVertexEcefMeters(const geo::Ellipsoid& ellipsoid,
                                      const terrain::BlockGrid& grid, uint32_t row, uint32_t column,
                                      double heightMeters) {
  const double latitudeDegrees = grid.latitudeDegrees(row);
  const RowTrig& r = rowTrig(ellipsoid, latitudeDegrees);
  const double z = (r.nPolar + heightMeters) * r.sinLat;
  if (std::abs(latitudeDegrees) == 90.0) return {0.0, 0.0, z};  // on the polar axis
  const ColumnTrig& c = columnTrig(grid.longitudeDegrees(column));
  const double rho = (r.n + heightMeters) * r.cosLat;
  return {rho * c.cosLon, rho * c.sinLon, z};
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
