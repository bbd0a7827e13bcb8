// Frustum plane extraction and frustum culling of RegionVolumes.
#include "geo/frustum.hpp"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>

namespace globe::geo {

namespace {

Plane normalisedPlane(const glm::dvec4& coefficients) {
  const glm::dvec3 normal{coefficients};
  const double length = glm::length(normal);
  // A zero normal (e.g. the far plane of an infinite projection) constrains nothing, or
  // everything when its constant term is negative.
  if (!(length > 0.0)) return {glm::dvec3{0.0}, coefficients.w >= 0.0 ? 0.0 : -1.0};
  return {normal / length, coefficients.w / length};
}

double signedDistance(const Plane& plane, const glm::dvec3& point) {
  return glm::dot(plane.normal, point) + plane.distance;
}

}  // namespace

Frustum Frustum::fromViewProjection(const glm::dmat4& viewProjection) {
  // glm is column-major: row i is (m[0][i], m[1][i], m[2][i], m[3][i]).
  const auto row = [&](int i) {
    return glm::dvec4{viewProjection[0][i], viewProjection[1][i], viewProjection[2][i],
                      viewProjection[3][i]};
  };
  const glm::dvec4 w = row(3);
  return {{normalisedPlane(w + row(0)), normalisedPlane(w - row(0)), normalisedPlane(w + row(1)),
           normalisedPlane(w - row(1)), normalisedPlane(w + row(2)), normalisedPlane(w - row(2))}};
}

CullResult cullRegion(const Frustum& frustum, const RegionVolume& volume) {
  if (!volume.bounded) return CullResult::Intersecting;
  bool inside = true;
  for (const Plane& plane : frustum.planes) {
    const double centerDistance = signedDistance(plane, volume.centerEcefMeters);
    if (centerDistance < -volume.radiusMeters) return CullResult::Outside;
    if (centerDistance >= volume.radiusMeters) continue;
    // The sphere straddles the plane: decide with the hull points, widened by the margin.
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -std::numeric_limits<double>::infinity();
    for (const glm::dvec3& point : volume.pointsEcefMeters) {
      const double distance = signedDistance(plane, point);
      lowest = std::min(lowest, distance);
      highest = std::max(highest, distance);
    }
    if (highest + volume.marginMeters < 0.0) return CullResult::Outside;
    if (lowest - volume.marginMeters < 0.0) inside = false;
  }
  return inside ? CullResult::Inside : CullResult::Intersecting;
}

CullResult cullRegion(const Frustum& frustum, const BoundingRegion& region,
                      const Ellipsoid& ellipsoid) {
  return cullRegion(frustum, RegionVolume::fromRegion(region, ellipsoid));
}

}  // namespace globe::geo
