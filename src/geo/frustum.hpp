// View-frustum planes extracted from a view-projection matrix, and conservative frustum culling
// of bounding regions.
#pragma once

#include <array>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "geo/bounding_region.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::geo {

// The half-space normal . p + distance >= 0 is inside; normal is unit length (or zero for a
// degenerate plane, which is then all-inside, distance 0, or all-outside, distance -1).
struct Plane {
  glm::dvec3 normal;
  double distance;
};

struct Frustum {
  // Order: left, right, bottom, top, near, far.
  std::array<Plane, 6> planes;

  // Gribb-Hartmann extraction with OpenGL clip conventions (-w <= x, y, z <= w), normalised.
  // The matrix maps world (here ECEF) positions to clip space.
  static Frustum fromViewProjection(const glm::dmat4& viewProjection);
};

enum class CullResult { Outside, Intersecting, Inside };

// Conservative: Outside only if no point of the region is inside the frustum, Inside only if
// every point is. Cheap: a bounding-sphere test per plane, then the hull points if needed.
CullResult cullRegion(const Frustum& frustum, const RegionVolume& volume);
// Convenience that builds the RegionVolume each call; prefer the overload above per frame.
CullResult cullRegion(const Frustum& frustum, const BoundingRegion& region,
                      const Ellipsoid& ellipsoid);

}  // namespace globe::geo
