#include "tiles3d/triangle_mesh.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace globe::tiles3d {
namespace {

glm::vec3 turned(const glm::dmat3& normalMatrix, const glm::vec3& n) {
  if (n == glm::vec3(0.0f)) return n;  // none given: made flat where drawn
  const glm::dvec3 t = normalMatrix * glm::dvec3(n);
  const double length = glm::length(t);
  return length > 0 ? glm::vec3(t / length) : glm::vec3(0.0f);
}

}  // namespace

void TriangleMesh::transform(const glm::dmat4& m) {
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(m)));
  for (glm::dvec3& p : positions) p = glm::dvec3(m * glm::dvec4(p, 1.0));
  for (glm::vec3& n : normals) n = turned(normalMatrix, n);
}

void TriangleMesh::append(const TriangleMesh& other, const glm::dmat4& m) {
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(m)));
  const auto firstPart = static_cast<uint32_t>(parts.size());
  parts.insert(parts.end(), other.parts.begin(), other.parts.end());
  for (const uint32_t part : other.triangleParts) triangleParts.push_back(firstPart + part);
  for (const glm::dvec3& p : other.positions)
    positions.push_back(glm::dvec3(m * glm::dvec4(p, 1.0)));
  for (const glm::vec3& n : other.normals) normals.push_back(turned(normalMatrix, n));
  uvs.insert(uvs.end(), other.uvs.begin(), other.uvs.end());
  pointPrimitives += other.pointPrimitives;
}

}  // namespace globe::tiles3d
