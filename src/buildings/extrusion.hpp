// A footprint extruded into a closed-looking solid on the ellipsoid: vertical walls from its base
// height to its roof height along each ring's edges (holes' walls face into the courtyard) and a
// flat roof (roof_triangulation.hpp); no floor (it stands in the ground). Every face has vertices
// of its own, so each carries its flat normal. Triangles are counter-clockwise seen from outside.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "buildings/footprint.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::buildings {

struct BuildingMesh {
  std::vector<glm::dvec3> positionsEcefMeters;
  std::vector<glm::vec3> normals;  // unit, ECEF axes
  std::vector<uint32_t> indices;   // three per triangle
  size_t triangleCount() const { return indices.size() / 3; }
};

// Appends the building standing from baseHeightMeters to roofHeightMeters (above the
// ellipsoid) to `mesh`. Returns the roof's triangles (0: a degenerate footprint, walls only).
size_t appendBuilding(const Footprint& footprint, double baseHeightMeters, double roofHeightMeters,
                      const geo::Ellipsoid& ellipsoid, BuildingMesh& mesh);

}  // namespace globe::buildings
