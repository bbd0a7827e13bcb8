// The exact height of the rendered surface under a point: the plane of the mesh triangle (NW-SE
// diagonal rule of tile_mesh.hpp) cut by the Oriented Ray, in double precision.
#pragma once

#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>

#include "collision/terrain_array.hpp"
#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"

namespace globe::collision {

// A triangle whose plane is within this cosine of containing the normal is degenerate...
inline constexpr double kMinimumNormalCosine = 1e-6;
// ...and a meeting point this far outside a triangle (in barycentric terms) still inside it:
// surface samplers that repeat the plane step for speed (surface/lattice_heights.cpp) use these.
inline constexpr double kBarycentricTolerance = 1e-9;

enum class SurfaceTriangle {
  None,         // no surface (no tile, invalid input)
  SouthWest,    // {(i,j), (i+1,j), (i+1,j+1)} of quad (i, j)
  NorthEast,    // {(i,j), (i+1,j+1), (i,j+1)} of quad (i, j)
  Pole,         // on a pole row: the highest of its vertices (all on the polar axis)
  QuadMaximum,  // both triangles of the quad degenerate: the highest of its four vertices
  Tin,          // a TIN tile's triangle (quadRow holds its index)
};

struct SurfaceSample {
  double heightMeters = 0.0;
  SurfaceTriangle triangle = SurfaceTriangle::None;
  uint32_t quadRow = 0;  // the quad of the triangle (its north-west vertex)
  uint32_t quadColumn = 0;
};

// Height above the ellipsoid, along the geodetic normal n at (lon, lat), of the point where the
// normal line through (lon, lat, 0) meets the tile's rendered mesh (the Oriented Ray from any
// camera above (lon, lat) meets the surface there). Vertices are built as the mesh builds them,
// in double (terrain::tileVertexEcefMeters of the surface height).
// - The triangle: quad (i, j) from the grid location, then by the DIAGONAL RULE of
//   tile_mesh.hpp the south-west half when rowFraction >= columnFraction (the diagonal itself
//   goes to that half), else the north-east half.
// - Its plane: with S the ellipsoid point, P0 a vertex and N the normal of the plane,
//   h = N.(P0 - S) / N.n.
// - The mesh's straight edges are not lines of constant latitude or slope (a parallel is not a
//   great circle), so the ray can meet the plane just outside the triangle, in slivers along the
//   rows and the diagonals (~0.5% of a cell at level 0, ~1e-5 at level 10). It then steps, at most
//   4 times, to the neighbouring triangle across the edge it is beyond (within the tile) and
//   uses that plane: the result is the triangle the ray really hits. At the tile border the
//   border triangle's plane is extended (the ray falls between this tile and its neighbour).
// - A degenerate triangle (zero area, or a plane within ~1e-6 rad of containing n), such as the
//   collapsed half of a pole quad, is replaced by the other half of its quad.
// - A TIN tile (the block's `tin`): its triangle under the point (terrain/tin_tile.hpp), the plane
//   of its vertices as the mesh draws them.
// The point must be contained in the tile (canonical longitude, tile_containment.hpp). A tile
// without a readable block (hasReadableBlock) gives {0, None}.
SurfaceSample exactTileSurfaceHeight(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid,
                                     double longitudeRadians, double latitudeRadians);

struct ExactSurfaceSample {
  double heightMeters = 0.0;
  SurfaceTriangle triangle = SurfaceTriangle::None;
  geo::TileId tile{};
};

// exactTileSurfaceHeight in the tile findIndexed picks; nullopt when no tile holds the point.
std::optional<ExactSurfaceSample> exactSurfaceHeight(const RenderingTileArray& array,
                                                     const geo::Ellipsoid& ellipsoid,
                                                     double longitudeRadians,
                                                     double latitudeRadians);

// Collision against the exact surface. With D the camera's geodetic height and E the exact
// surface height under it, the ray from the camera along -n meets the triangle's plane at
// distance D - E, and collided = D <= E + clearance (the same test as QOTCD with H replaced by
// E). valid == false (everything else false/0) when the camera has no geodetic coordinates;
// found == false: no tile holds the nadir, E is taken as 0 m (sea level).
struct ExactSurfaceResult {
  bool valid = false;
  bool found = false;
  bool collided = false;
  double surfaceHeightMeters = 0.0;  // E
  double cameraHeightMeters = 0.0;   // D
  geo::TileId tile{};
  SurfaceTriangle triangle = SurfaceTriangle::None;
};
ExactSurfaceResult exactSurfaceTest(const RenderingTileArray& array,
                                    const geo::Ellipsoid& ellipsoid,
                                    const glm::dvec3& cameraEcefMeters, double clearanceMeters);

}  // namespace globe::collision
