// Brute-force oracle for the exact surface: casts the Oriented Ray against every grid triangle
// of a tile's mesh (double ECEF vertices as tile_mesh builds them) and keeps the first hit.
#pragma once

#include <cstdint>
#include <optional>

#include "collision/terrain_array.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::collision::testing {

struct MeshHit {
  double heightMeters;  // of the hit point, along the normal at (lon, lat)
  uint32_t quadRow;
  uint32_t quadColumn;
  bool southWest;  // which half of the quad (tile_mesh.hpp DIAGONAL RULE)
};

// The ray comes down from 100 km above (lon, lat); triangles are hit with a small tolerance on
// their edges (1e-9 in barycentric terms).
std::optional<MeshHit> castOntoTileMesh(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid,
                                        double longitudeRadians, double latitudeRadians);

}  // namespace globe::collision::testing
