// The paper's camera-terrain collision responses (section 3.3) as pure functions of the camera's
// valid position, the proposed motion and the rendering tile array: stop, slide, heighten.
#pragma once

#include <cstdint>
#include <string_view>

#include <glm/vec3.hpp>

#include "collision/surface_probe.hpp"
#include "collision/swept_test.hpp"
#include "collision/terrain_array.hpp"
#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::collision {

enum class Response {
  None,
  Stopped,              // static camera: the move was refused, the last valid pose kept
  Slid,                 // linear motion: slid along the terrain's tangent plane
  Heightened,           // angular motion: raised, the angular motion applied in full
  RaisedForNewTerrain,  // the surface rose under a camera that did not collide by moving
  NearPlanePushed,      // raised so that the near plane's corners clear the drawn surface
};
std::string_view toString(Response response);

// A point collides when it is more than this below its clearance, and a response places it at
// the clearance itself: a camera sliding along a plane at its clearance does not collide again
// through rounding (the "skin" of physics engines). Results keep clearance - skin at least.
inline constexpr double kContactSkinMeters = 0.01;

struct ResponseSettings {
  SurfaceModel surface = SurfaceModel::Exact;
  bool sweep = true;  // false: the paper's test of the end position only (tunnels through ridges)
  SweepSettings sweepSettings;
  int maxSlideIterations = 4;  // contacts per frame; the rest of the motion is dropped after them
};

struct MotionResult {
  bool valid = false;            // false: no geodetic coordinates on the way (non-finite input)
  geo::Cartographic position{};  // where the camera ends (longitude in [-pi, pi))
  Response response = Response::None;  // None, Stopped, Slid or Heightened
  glm::dvec3 contactNormal{0.0};       // Slid: the normal of the last surface slid along
  geo::Cartographic firstContact{};    // Slid with the sweep: where the motion first stopped
  int slideIterations = 0;             // Slid: contacts met
  double liftMeters = 0.0;             // Heightened: how far the end was raised
  uint32_t samples = 0;                // surface probes
  uint32_t tilesExamined = 0;          // QOTCD hash probes
};

// 3.3.1 Static camera (no velocity, no acceleration; a jump): the proposed position is tested;
// when it collides the move is refused (Stopped) and position = from. Otherwise position = to.
MotionResult respondStatic(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                           const geo::Cartographic& from, const geo::Cartographic& to,
                           double clearanceMeters, const ResponseSettings& settings);

// 3.3.2 Linear velocity: the camera moves by displacementEcefMeters from `from`. With the sweep
// the motion stops at the first contact (raised to the clearance), the rest of it is projected
// onto the tangent plane of the drawn triangle hit (its component into the surface removed) and
// swept again, up to maxSlideIterations contacts. Without it (the paper) the end is tested and
// the motion projected on the triangle under it until the end is free. Either way the end is
// finally raised to the clearance if it is still below it, never below the surface.
MotionResult respondLinear(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                           const geo::Cartographic& from, const glm::dvec3& displacementEcefMeters,
                           double clearanceMeters, const ResponseSettings& settings);

// 3.3.2 Angular velocity about the globe centre: the camera turns from `from` to `to` (the end
// of the rotation); the angular motion is applied in full (the end's longitude and latitude are
// to's) and only the height is raised, to the model's surface + clearance where the end collides
// or, with the sweep, by the largest lift the arc needed (sweepArc: a ridge crossed during the
// frame lifts the camera over it, and it stays lifted, as the paper's heightening does).
MotionResult respondAngular(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                            const geo::Cartographic& from, const geo::Cartographic& to,
                            double clearanceMeters, const ResponseSettings& settings);

}  // namespace globe::collision
