// Triangles as a soup (three positions a triangle): what a 3D tile's content gives collision.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

namespace globe::tiles3d {

struct TriangleMesh {
  std::vector<glm::dvec3> positions;  // three per triangle
  size_t pointPrimitives = 0;         // points and lines read past (no surface to stand on)
  size_t triangleCount() const { return positions.size() / 3; }
};

}  // namespace globe::tiles3d
