// Test support for the responses and the controller: real tile arrays over Fuji and the globe,
// tangent-plane offsets, and the per-frame audit of the eye and near plane above the surface.
#pragma once

#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>

#include "camera/camera_motion.hpp"
#include "camera/camera_pose.hpp"
#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"
#include "terrain/rendering_tile_array.hpp"

namespace globe::camera::testing {

// Kengamine, the summit of Mount Fuji (3776 m; ~3731 m on the drawn 3" surface).
inline constexpr double kFujiSummitLongitudeDegrees = 138.7275;
inline constexpr double kFujiSummitLatitudeDegrees = 35.3606;
geo::Cartographic fujiSummit(double heightMeters = 0.0);

// The bundled pyramid's finest level (14 over Fuji).
uint32_t finestLevel();

// A quadtree cut covering the globe: tiles intersecting the box 138.55..138.90 E,
// 35.22..35.50 N (Fuji and its slopes, ~30 km) refined down to `level`, coarser away from it.
// Cached per level for the whole run.
const terrain::RenderingTileArray& fujiArray(uint32_t level);
// A quadtree cut covering the globe at level 2, refined to the pyramid's finest (ETOPO20, ~level 5)
// at |latitude| >= 80 deg and |longitude| >= 175 deg.
const terrain::RenderingTileArray& globalArray();

// The drawn surface under (lon, lat): exactSurfaceHeight, 0 m where no tile holds it.
double drawnHeight(const terrain::RenderingTileArray& array, double longitudeRadians,
                   double latitudeRadians);

// fujiArray(finestLevel()), and the surface it draws under a position.
const terrain::RenderingTileArray& fuji();
double drawn(const geo::Cartographic& position);

// The point distanceMeters from `origin` along the local tangent plane towards bearingRadians
// (0 = north, clockwise), at heightMeters.
geo::Cartographic offsetPosition(const geo::Cartographic& origin, double bearingRadians,
                                 double distanceMeters, double heightMeters);
// The unit ECEF direction of heading/pitch at a position (the camera's forward).
glm::dvec3 direction(const geo::Cartographic& position, double headingRadians, double pitchRadians);

// How far the view from the eye to the near plane reaches below the drawn surface (metres; <= 0:
// not at all), by an oracle written apart from the collision code: rays from the eye to a 5 x 5
// grid over the near-plane rectangle, each sampled at 1/4, 1/2, 3/4 and 1, against the
// brute-force mesh ray cast (tests/collision/mesh_ray_cast.hpp); the eye itself too.
double deepestInsideView(const CameraPose& pose, const NearPlane& nearPlane,
                         const terrain::RenderingTileArray& array);

// Counts frames whose eye or near-plane corners are below the drawn surface (+ 0 m), or whose
// pose is not finite; keeps the lowest clearances seen.
struct FrameAudit {
  int frames = 0;
  int violations = 0;
  int nonFinite = 0;
  double lowestEyeClearanceMeters = std::numeric_limits<double>::infinity();
  double lowestCornerClearanceMeters = std::numeric_limits<double>::infinity();
  // Returns false when this frame is a violation.
  bool check(const CameraPose& pose, const NearPlane& nearPlane,
             const terrain::RenderingTileArray& array);
  void add(const FrameAudit& other);
};

}  // namespace globe::camera::testing
