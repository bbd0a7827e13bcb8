// QOTCD (Quick Oriented Terrain Collision Detection) as the paper states it, with the paper's
// linear tile scan and with an indexed O(1)-per-level tile lookup giving the same answers.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "collision/qotcd_height.hpp"
#include "collision/terrain_array.hpp"
#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"

namespace globe::collision {

// Steps: the camera's geodetic (lon, lat, D) by geo::ecefToCartographic (the paper's formula
// (1) made robust; D is the height along the Oriented Ray: towards the centre on the sphere,
// along the geodetic normal on WGS84); the Intersecting Terrain Tile holding (lon, lat) (see
// RenderingTileArray); early-out when D > tile maximum + clearance (the block is not read,
// H = the tile maximum); else H from the block (qotcdTileHeight); collided = D <= H + clearance.
// - valid == false: the camera has no geodetic coordinates (a non-finite component, or within
//   geo::kGeocentreThresholdMeters of the centre); everything else is false / 0 / None and the
//   caller should reject the pose. No NaN is ever returned.
// - found == false: no tile holds (lon, lat); H is then 0 m (sea level), so
//   collided = D <= clearance.
// - A non-finite clearance counts as 0.
struct QotcdResult {
  using Case = HeightCase;
  bool valid = false;
  bool found = false;
  bool collided = false;
  bool earlyOut = false;             // the block was not read
  double terrainHeightMeters = 0.0;  // H
  double cameraHeightMeters = 0.0;   // D
  double longitudeRadians = 0.0;     // the Intersecting Point, longitude in [-pi, pi)
  double latitudeRadians = 0.0;
  geo::TileId tile{};  // the Intersecting Terrain Tile when found
  Case heightCase = Case::None;
  uint32_t tilesExamined = 0;  // linear: bounds tests; indexed: hash probes
};

QotcdResult qotcdLinear(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                        const glm::dvec3& cameraEcefMeters, double clearanceMeters);
QotcdResult qotcdIndexed(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                         const glm::dvec3& cameraEcefMeters, double clearanceMeters);

// The same from the camera's geodetic coordinates (heightMeters = D), for callers that have them
// and for exact placement on edges; invalid when non-finite or |latitude| > pi/2.
QotcdResult qotcdLinear(const RenderingTileArray& array, const geo::Cartographic& camera,
                        double clearanceMeters);
QotcdResult qotcdIndexed(const RenderingTileArray& array, const geo::Cartographic& camera,
                         double clearanceMeters);

// Totals over many queries (e.g. one frame's, or a benchmark's).
struct QotcdCounters {
  uint64_t queries = 0;
  uint64_t invalid = 0;
  uint64_t notFound = 0;
  uint64_t collisions = 0;
  uint64_t earlyOuts = 0;
  uint64_t blockReads = 0;
  uint64_t tilesExamined = 0;

  void add(const QotcdResult& result);
};

}  // namespace globe::collision
