#include "buildings/extrusion.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "buildings/roof_triangulation.hpp"
#include "geo/ecef.hpp"

namespace globe::buildings {
namespace {

// East, north and up at the footprint's centre: the plane the roof is triangulated in.
struct LocalFrame {
  glm::dvec3 originEcef, east, north, up;
  glm::dvec2 toPlane(const glm::dvec3& ecef) const {
    const glm::dvec3 d = ecef - originEcef;
    return {glm::dot(d, east), glm::dot(d, north)};
  }
};

LocalFrame frameAt(const RingDegrees& outer, const geo::Ellipsoid& ellipsoid) {
  glm::dvec2 sum(0.0);
  for (const glm::dvec2& p : outer) sum += p;
  const glm::dvec2 centre = sum / static_cast<double>(outer.size());
  const geo::Cartographic c = geo::Cartographic::fromDegrees(centre.x, centre.y);
  LocalFrame f;
  f.originEcef = geo::cartographicToEcef(ellipsoid, c);
  f.up = geo::geodeticSurfaceNormal(ellipsoid, c);
  f.east =
      glm::normalize(glm::dvec3(-std::sin(c.longitudeRadians), std::cos(c.longitudeRadians), 0));
  f.north = glm::cross(f.up, f.east);
  return f;
}

glm::dvec3 ecefOf(const glm::dvec2& degrees, double heightMeters, const geo::Ellipsoid& e) {
  return geo::cartographicToEcef(
      e, geo::Cartographic::fromDegrees(degrees.x, degrees.y, heightMeters));
}

// Appends a triangle of three new vertices with the face's normal, wound counter-clockwise about
// `normal` whatever order the corners come in.
void addFace(BuildingMesh& mesh, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c,
             const glm::dvec3& normal) {
  if (glm::dot(glm::cross(b - a, c - a), normal) < 0) std::swap(b, c);
  const auto first = static_cast<uint32_t>(mesh.positionsEcefMeters.size());
  for (const glm::dvec3& p : {a, b, c}) {
    mesh.positionsEcefMeters.push_back(p);
    mesh.normals.emplace_back(normal);
  }
  mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2});
}

// The walls of one ring: outward is to the right of travel once the outer ring runs
// counter-clockwise and the holes clockwise (seen from above).
void appendWalls(const RingDegrees& ring, const PlaneRing& plane, bool hole, double baseMeters,
                 double roofMeters, const LocalFrame& frame, const geo::Ellipsoid& ellipsoid,
                 BuildingMesh& mesh) {
  const bool reverse = (signedAreaSquareMeters(plane) > 0) == hole;
  const size_t n = ring.size();
  for (size_t k = 0; k < n; ++k) {
    size_t i = k, j = (k + 1) % n;
    if (reverse) i = n - 1 - k, j = (2 * n - 2 - k) % n;
    const glm::dvec2 d = plane[j] - plane[i];
    const double length = std::hypot(d.x, d.y);
    if (!(length > 1e-6)) continue;
    const glm::dvec3 outward =
        glm::normalize(frame.east * (d.y / length) - frame.north * (d.x / length));
    const glm::dvec3 a0 = ecefOf(ring[i], baseMeters, ellipsoid),
                     b0 = ecefOf(ring[j], baseMeters, ellipsoid);
    const glm::dvec3 a1 = ecefOf(ring[i], roofMeters, ellipsoid),
                     b1 = ecefOf(ring[j], roofMeters, ellipsoid);
    addFace(mesh, a0, b0, b1, outward);
    addFace(mesh, a0, b1, a1, outward);
  }
}

}  // namespace

size_t appendBuilding(const Footprint& footprint, double baseHeightMeters, double roofHeightMeters,
                      const geo::Ellipsoid& ellipsoid, BuildingMesh& mesh) {
  if (footprint.rings.empty() || footprint.rings.front().size() < 3) return 0;
  const LocalFrame frame = frameAt(footprint.rings.front(), ellipsoid);
  std::vector<PlaneRing> planes;
  std::vector<glm::dvec3> roof;
  for (const RingDegrees& ring : footprint.rings) {
    PlaneRing plane;
    for (const glm::dvec2& p : ring) {
      roof.push_back(ecefOf(p, roofHeightMeters, ellipsoid));
      plane.push_back(frame.toPlane(ecefOf(p, 0, ellipsoid)));
    }
    planes.push_back(std::move(plane));
  }
  for (size_t r = 0; r < footprint.rings.size(); ++r) {
    appendWalls(footprint.rings[r], planes[r], r > 0, baseHeightMeters, roofHeightMeters, frame,
                ellipsoid, mesh);
  }
  const std::vector<uint32_t> triangles = triangulatePolygon(planes);
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    addFace(mesh, roof[triangles[t]], roof[triangles[t + 1]], roof[triangles[t + 2]], frame.up);
  }
  return triangles.size() / 3;
}

}  // namespace globe::buildings
