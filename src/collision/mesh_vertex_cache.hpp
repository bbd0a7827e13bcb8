// The drawn mesh's vertices in ECEF, bit for bit as terrain::tileVertexEcefMeters computes them,
// with the sines, cosines and radii of curvature of recently used grid rows and columns kept (per
// thread, a small direct-mapped table), so the exact surface does not pay six sincos a query; and
// the nadir point with its normal from one set of sines and cosines.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "geo/ellipsoid.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/height_block.hpp"

namespace globe::collision {

glm::dvec3 cachedTileVertexEcefMeters(const geo::Ellipsoid& ellipsoid,
                                      const terrain::BlockGrid& grid, uint32_t row, uint32_t column,
                                      double heightMeters);

// Every vertex of a block, row-major, each as cachedTileVertexEcefMeters gives it (the block's
// surfaceHeightMetersAt), the sines and cosines of its rows and columns worked out once: for
// samplers that read many points of one block.
std::vector<glm::dvec3> blockVertexEcefMeters(const geo::Ellipsoid& ellipsoid,
                                              const terrain::BlockGrid& grid,
                                              const terrain::HeightBlock& block);

struct SurfacePoint {
  glm::dvec3 pointEcefMeters;  // geo::cartographicToEcef at height 0
  glm::dvec3 normal;           // geo::geodeticSurfaceNormal
};
SurfacePoint surfacePointAndNormal(const geo::Ellipsoid& ellipsoid, double longitudeRadians,
                                   double latitudeRadians);

}  // namespace globe::collision
