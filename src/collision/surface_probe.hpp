// The surface under one point as the responses see it: QOTCD (the paper's quick, conservative
// test) as the broad phase, the drawn triangle as the narrow phase, and that triangle's normal.
#pragma once

#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>

#include "collision/terrain_array.hpp"
#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::collision {

// The height the responses keep the camera above.
enum class SurfaceModel {
  Exact,  // the drawn surface (exactTileSurfaceHeight); QOTCD only decides what is far from it
  Qotcd,  // QOTCD's H (the highest vertex of the quad, the paper's rule): higher on slopes
};

// QOTCD's H can lie below the drawn surface by < 1 mm (rows at high latitude, steep slopes). The
// broad phase adds this to the clearance, so it never clears a point the narrow phase would not.
inline constexpr double kQotcdAllowanceMeters = 0.01;

struct SurfaceProbe {
  bool valid = false;        // the point has geodetic coordinates (finite, |latitude| <= pi/2)
  bool found = false;        // a tile holds its nadir; where none does the surface is 0 m (sea)
  bool collided = false;     // position.heightMeters < surfaceHeightMeters + clearance
  bool surfaceRead = false;  // false: QOTCD cleared the point and surfaceHeightMeters is its H
                             // (an upper bound of the model's height, e.g. the tile maximum)
  double surfaceHeightMeters = 0.0;
  geo::Cartographic position{};     // the point, longitude canonical in [-pi, pi)
  const ArrayTile* tile = nullptr;  // the Intersecting Terrain Tile when found
  uint32_t tilesExamined = 0;       // QOTCD's hash probes
};

// QOTCD (qotcdIndexed) with clearance + kQotcdAllowanceMeters; only where it reports a collision
// is the model's height read in the tile it found and the test repeated with the clearance.
SurfaceProbe probeSurface(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                          const geo::Cartographic& point, double clearanceMeters,
                          SurfaceModel model);

struct SurfaceHeight {
  double heightMeters = 0.0;  // 0 m (sea level) where no tile holds the point
  bool found = false;
  const ArrayTile* tile = nullptr;
};
// The model's height under (lon, lat) with no broad phase; nullopt for invalid input.
std::optional<SurfaceHeight> surfaceHeightAt(const RenderingTileArray& array,
                                             const geo::Ellipsoid& ellipsoid,
                                             double longitudeRadians, double latitudeRadians,
                                             SurfaceModel model);

// Unit normal (ECEF, pointing up) of the drawn triangle under (lon, lat): the triangle
// exactTileSurfaceHeight hits, its vertices built as the mesh builds them. The ellipsoid normal
// where there is no triangle (no tile, a pole row, a degenerate quad) or for invalid input.
glm::dvec3 surfaceNormalAt(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                           double longitudeRadians, double latitudeRadians);

// Metres between neighbouring vertices of the tile along a meridian (the equatorial radius times
// the angular spacing); along a parallel they are closer by cos(latitude).
double vertexSpacingMeters(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid);

// The highest surface anywhere: the largest tile maximum, and 0 m (the sea where no tile is).
double maximumSurfaceHeightMeters(const RenderingTileArray& array);

}  // namespace globe::collision
