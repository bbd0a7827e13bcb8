// The rules deciding which tile of a rendering tile array holds a point, shared by the paper's
// linear scan and the indexed lookup so that the two always agree.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>

#include "geo/cartographic.hpp"
#include "terrain/rendering_tile_array.hpp"

namespace globe::terrain {

enum class Pole { None, North, South };

// A lookup point in canonical form: longitude in [-pi, pi) (+pi is stored as -pi, the same
// meridian), latitude in [-pi/2, pi/2], pole set when the latitude is exactly +-pi/2.
struct QueryPoint {
  double longitudeRadians;
  double latitudeRadians;
  Pole pole;
};

// Wraps the longitude (geo::wrapLongitudeRadians), maps +pi to -pi; nullopt for non-finite
// input or |latitude| > pi/2.
// Inline: every collision query starts here.
inline std::optional<QueryPoint> makeQueryPoint(double longitudeRadians, double latitudeRadians) {
  constexpr double kPi = std::numbers::pi;
  constexpr double kHalfPi = std::numbers::pi / 2.0;
  if (!std::isfinite(longitudeRadians) || !std::isfinite(latitudeRadians) ||
      std::abs(latitudeRadians) > kHalfPi) {
    return std::nullopt;
  }
  double longitude = longitudeRadians >= -kPi && longitudeRadians <= kPi
                         ? longitudeRadians
                         : geo::wrapLongitudeRadians(longitudeRadians);
  if (longitude >= kPi) longitude = -kPi;
  Pole pole = Pole::None;
  if (latitudeRadians == kHalfPi) pole = Pole::North;
  if (latitudeRadians == -kHalfPi) pole = Pole::South;
  return QueryPoint{longitude, latitudeRadians, pole};
}

// Closed bounds: west <= lon <= east and south <= lat <= north (4 comparisons); also true for
// lon = -pi in a tile whose east edge is +pi, and for a pole in every tile touching it.
bool containsClosed(const ArrayTile& tile, const QueryPoint& point);

// Orders the tiles that contain the point (containsClosed): higher wins. Finer levels first;
// within a level the key follows the scheme's half-open rule [west, east) x (south, north]
// (lat = -pi/2 belongs to the last row): owning in both > owning the latitude (the southern
// tile) > owning the longitude (the eastern tile) > neither. At a pole: the tile owning the
// longitude, then the smallest x. Two distinct containing tiles never get equal keys.
uint64_t selectionKey(const ArrayTile& tile, const QueryPoint& point);

// The tile's longitude for a canonical point: lon + 2 pi when the tile holds -pi on its +pi edge.
// Inline: every collision query calls it.
inline double longitudeInTile(const ArrayTile& tile, double longitudeRadians) {
  constexpr double kPi = std::numbers::pi;
  if (longitudeRadians < tile.westRadians && tile.eastRadians >= kPi) {
    return longitudeRadians + 2.0 * kPi;
  }
  return longitudeRadians;
}

}  // namespace globe::terrain
