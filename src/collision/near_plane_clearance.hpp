// Clearance of the near plane, not only of the eye: points rigidly attached to the eye (the near
// plane's corners) must stay above the drawn surface; the camera is pushed up by the worst miss.
#pragma once

#include <optional>
#include <span>

#include <glm/vec3.hpp>

#include "collision/surface_probe.hpp"
#include "collision/terrain_array.hpp"
#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::collision {

struct NearPlaneResult {
  bool valid = false;            // false: the eye or a corner had no geodetic coordinates
  geo::Cartographic position{};  // the eye after the push (longitude and latitude unchanged)
  double pushMeters = 0.0;       // how far it was raised (0: nothing to do)
  // The lowest of the points above the model's surface, before and after the push.
  double lowestClearanceBeforeMeters = 0.0;
  double lowestClearanceAfterMeters = 0.0;
};

// The lowest clearance of the points eye + offset (ECEF) above the model's surface under them
// (0 m where no tile); nullopt when a point has no geodetic coordinates or there are none.
std::optional<double> lowestPointClearance(const RenderingTileArray& array,
                                           const geo::Ellipsoid& ellipsoid,
                                           const geo::Cartographic& eye,
                                           std::span<const glm::dvec3> offsetsEcefMeters,
                                           SurfaceModel model);

// Each point eye + offset (ECEF) is converted to geodetic (lon, lat, h) and compared with the
// model's surface E under it (0 m where no tile). With v = max(E + clearance - h), the eye is
// raised along its ellipsoid normal by v (plus 1 mm) when v > 0, and the test repeated (the
// points' normals differ from the eye's by ~1e-7 rad), up to 4 times. No offsets: no push.
NearPlaneResult pushAboveNearPlane(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                                   const geo::Cartographic& eye,
                                   std::span<const glm::dvec3> offsetsEcefMeters,
                                   double clearanceMeters, SurfaceModel model);

}  // namespace globe::collision
