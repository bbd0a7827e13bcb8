// One mesh vertex before packing (tile_mesh.cpp and tin_mesh.cpp build them; packMeshVertices
// writes them in tile_mesh.hpp's interleaved layout).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "terrain/tile_mesh.hpp"

namespace globe::terrain {

struct MeshVertex {
  glm::dvec3 positionEcef;
  glm::dvec3 normal;
  glm::dvec3 coarseNormal;   // the next coarser level's normal here (edge vertices; else normal)
  double heightMeters;       // where the vertex is drawn: the block's surface height
  double colorHeightMeters;  // what its colour shows: the land height, or the sea floor
  float sea;
  float u, v;
};

// Fills mesh.vertices and mesh.centerEcefMeters (on the level's origin quantum, so the float
// offsets are exact).
void packMeshVertices(const std::vector<MeshVertex>& vertices, uint32_t level, TileMesh& mesh);

}  // namespace globe::terrain
