// A tile's bounding volume as the sphere around it in ECEF: what culling and the screen-space
// error need. A 3D Tiles `sphere` and `box` go through the tile's transform (the box's eight
// corners bounded exactly), a `region` (radians and metres, never transformed, as the spec says)
// through the ellipsoid, its curvature between the points sampled allowed for.
#pragma once

#include <limits>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json_fwd.hpp>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::tiles3d {

struct BoundingSphere {
  glm::dvec3 centerEcefMeters{0.0};
  double radiusMeters = std::numeric_limits<double>::infinity();  // infinite: no volume given

  // From the camera to the sphere's surface; 0 inside it.
  double distanceMeters(const glm::dvec3& pointEcefMeters) const;
};

// `volume`: a tile's "boundingVolume" object; `transform`: the tile's transform chain. Errors
// name `name` and say what is wrong (a volume of the wrong length, not finite, an empty one).
Result<BoundingSphere> boundingSphereOf(const nlohmann::json& volume, const glm::dmat4& transform,
                                        const geo::Ellipsoid& ellipsoid, const std::string& name);

}  // namespace globe::tiles3d
