// One tile's GPU copy: its vertex buffer, and a vertex array binding it with the shared index
// buffer in the attribute layout of shaders/terrain.vert.
#pragma once

#include <cstdint>
#include <span>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "geo/tile_id.hpp"
#include "render/gl_object.hpp"
#include "terrain/texel_footprint.hpp"
#include "terrain/tile_mesh.hpp"

namespace globe::render {

// Attribute locations of shaders/terrain.vert.
inline constexpr GLuint kAttributeOffset = 0;
inline constexpr GLuint kAttributeNormal = 1;
inline constexpr GLuint kAttributeHeight = 2;
inline constexpr GLuint kAttributeSea = 3;
inline constexpr GLuint kAttributeUv = 4;
inline constexpr GLuint kAttributeCoarseNormal = 5;
inline constexpr GLuint kAttributeSunlight = 6;  // 0..1 of the Sun seen (shadows); else 1

struct GpuTile {
  GlObject vertexArray;
  GlObject vertexBuffer;
  glm::dvec3 centerEcefMeters{0.0};
  glm::vec4 imageryRect{0.0f};  // global equirectangular uv = xy + tile uv · zw
  double radiusMeters = 0.0;    // the farthest vertex (skirts included) from the centre
  terrain::TileBox box;         // around the vertices (skirts included), for texel footprints
  // Every vertex land (sea flag 0) or every vertex water (1): where a water mask says the same
  // over the whole tile, it changes nothing and is not sampled.
  bool allLand = false;
  bool allWater = false;
  uint64_t vertexBytes = 0;
  terrain::EdgeHeightHashes edgeHeightHashes{};  // the mesh's: which skirts a seam needs
  GlObject sunlightBuffer;  // one float a vertex (setGpuTileSunlight); none: attribute 6 is 1
  uint32_t verticesPerSide = 0;
  bool hasSkirts = false;
  // A TIN tile's own triangles (terrain/tin_mesh.hpp), skirts included, drawn whole; none (0
  // indices): the grid's shared buffer.
  GlObject indexBuffer;
  uint32_t indexCount = 0;
};

// Uploads the mesh's vertices (GL_STATIC_DRAW) and binds `indexBuffer` into the vertex array, or
// the mesh's own indices (a TIN tile's) uploaded beside them.
GpuTile uploadGpuTile(const geo::TileId& tile, const terrain::TileMesh& mesh, GLuint indexBuffer);

// Uploads the Sun's visibility at each grid vertex (row-major N×N, collision/sun_visibility.hpp)
// as attribute kAttributeSunlight, skirt vertices taking their edge vertex's; false when the
// count is not N² or the tile is a TIN (its vertices are not the grid's: no shadows on it).
bool setGpuTileSunlight(GpuTile& gpu, std::span<const float> gridVisibility);

}  // namespace globe::render
