// Triangles as a soup (three corners a triangle): what a 3D tile's content gives collision
// (positions) and drawing (normals, texture coordinates and the surface each triangle wears).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace globe::tiles3d {

// RGBA8, rows top-down as glTF's texture coordinates take them ((0, 0): the top-left corner).
struct MeshTexture {
  int widthPixels = 0, heightPixels = 0;
  std::vector<uint8_t> rgba;
};

// What a triangle wears: glTF's base colour, times its base colour texture where it has one.
// Alpha: MASK cuts at its cutoff; BLEND is drawn as MASK at 0.5 (no sorting of transparent
// triangles), so foliage cards show their leaves, not their black background.
struct SurfacePart {
  glm::vec4 baseColor{1.0f};
  std::shared_ptr<const MeshTexture> texture;
  float alphaCutoff = 0;  // 0: opaque
};

struct TriangleMesh {
  std::vector<glm::dvec3> positions;    // three per triangle
  std::vector<glm::vec3> normals;       // per corner; zero where the model gives none
  std::vector<glm::vec2> uvs;           // per corner; zero where untextured
  std::vector<uint32_t> triangleParts;  // per triangle, into parts
  std::vector<SurfacePart> parts;
  size_t pointPrimitives = 0;  // points and lines read past (no surface to stand on)
  size_t triangleCount() const { return positions.size() / 3; }

  // Every corner through `m` (normals through its inverse transpose).
  void transform(const glm::dmat4& m);
  // `other`'s triangles after these, through `m`, with their parts.
  void append(const TriangleMesh& other, const glm::dmat4& m);
};

}  // namespace globe::tiles3d
