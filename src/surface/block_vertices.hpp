// One block's mesh vertices in ECEF, worked out once for the many points a lattice samples in it,
// and the common case of collision's exact surface repeated on them: the plane of the first
// triangle a point's normal line meets, where that triangle holds the meeting point.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "geo/ellipsoid.hpp"
#include "surface/pyramid_surface.hpp"

namespace globe::surface {

struct BlockVertices {
  PyramidSurface::Loaded tile;  // block null: the pyramid has no tile there (0 m)
  // Row-major N×N, bit for bit the vertices collision::exactTileSurfaceHeight builds; empty
  // where the plane step does not apply (a TIN tile, a tile on a pole, an unreadable block).
  std::vector<glm::dvec3> ecefMeters;
  // collision::locateInGrid's terms that depend on the tile alone, worked out once as it would.
  double cells = 0.0, columnsPerRadian = 0.0, rowsPerRadian = 0.0;
};

BlockVertices prepareBlockVertices(PyramidSurface::Loaded tile, const geo::Ellipsoid& ellipsoid);

// collision::exactTileSurfaceHeight(block's tile, lon, lat).heightMeters, bit for bit, when the
// first triangle it tries (the diagonal rule) is not degenerate and holds the meeting point;
// nullopt where it would look further (then ask it). nadirEcefMeters and normal: the point at
// (lon, lat, 0) and the geodetic normal there, as collision::surfacePointAndNormal makes them.
std::optional<double> gridPlaneHeightMeters(const BlockVertices& block, double longitudeRadians,
                                            double latitudeRadians,
                                            const glm::dvec3& nadirEcefMeters,
                                            const glm::dvec3& normal);

}  // namespace globe::surface
