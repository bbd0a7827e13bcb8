// Canonical lookup points, closed containment and the tie-breaking key between tiles.
#include "terrain/tile_containment.hpp"

#include <cmath>
#include <numbers>

#include "geo/cartographic.hpp"

namespace globe::terrain {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kHalfPi = std::numbers::pi / 2.0;

// Half-open ownership along longitude: [west, east). A canonical point never has lon = +pi.
bool ownsLongitude(const ArrayTile& tile, double longitudeRadians) {
  return tile.westRadians <= longitudeRadians && longitudeRadians < tile.eastRadians;
}

}  // namespace

bool containsClosed(const ArrayTile& tile, const QueryPoint& point) {
  if (point.pole == Pole::North) return tile.northRadians >= kHalfPi;
  if (point.pole == Pole::South) return tile.southRadians <= -kHalfPi;
  const double lon = point.longitudeRadians;
  const double lat = point.latitudeRadians;
  if (lat < tile.southRadians || lat > tile.northRadians) return false;
  if (lon >= tile.westRadians && lon <= tile.eastRadians) return true;
  return lon == -kPi && tile.eastRadians >= kPi;
}

uint64_t selectionKey(const ArrayTile& tile, const QueryPoint& point) {
  // Level in the top bits; 34 bits below hold the within-level key.
  const uint64_t levelKey = uint64_t{tile.id.level} << 34;
  const bool ownsLon = ownsLongitude(tile, point.longitudeRadians);
  if (point.pole != Pole::None) {
    const uint64_t withinLevel =
        ownsLon ? (uint64_t{1} << 33) : (uint64_t{1} << 32) - 1 - tile.id.x;
    return levelKey | withinLevel;
  }
  // Rows are (south, north]; -pi/2 belongs to the southernmost row.
  const bool ownsLat = point.latitudeRadians > tile.southRadians || tile.southRadians <= -kHalfPi;
  return levelKey | (ownsLat ? 2u : 0u) | (ownsLon ? 1u : 0u);
}

}  // namespace globe::terrain
