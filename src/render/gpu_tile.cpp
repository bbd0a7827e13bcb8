// Vertex buffer upload and attribute setup for one tile.
#include "render/gpu_tile.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "geo/tiling_scheme.hpp"

namespace globe::render {
namespace {

void floatAttribute(GLuint location, GLint components, uint32_t offsetFloats) {
  constexpr auto stride = static_cast<GLsizei>(terrain::kTileVertexFloats * sizeof(float));
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(size_t{offsetFloats} * sizeof(float)));
}

}  // namespace

GpuTile uploadGpuTile(const geo::TileId& tile, const terrain::TileMesh& mesh, GLuint indexBuffer) {
  GpuTile gpu;
  gpu.centerEcefMeters = mesh.centerEcefMeters;
  const geo::GlobeRectangle rect = geo::GeographicTilingScheme::tileRectangle(tile);
  constexpr double pi = std::numbers::pi;
  gpu.imageryRect = glm::vec4(static_cast<float>((rect.westRadians + pi) / (2.0 * pi)),
                              static_cast<float>((pi / 2.0 - rect.northRadians) / pi),
                              static_cast<float>(rect.widthRadians() / (2.0 * pi)),
                              static_cast<float>(rect.heightRadians() / pi));
  gpu.vertexBytes = mesh.vertices.size() * sizeof(float);
  gpu.edgeHeightHashes = mesh.edgeHeightHashes;
  gpu.verticesPerSide = mesh.verticesPerSide;
  gpu.hasSkirts = mesh.hasSkirts;
  double radiusSquared = 0.0;
  gpu.allLand = gpu.allWater = !mesh.vertices.empty();
  for (size_t k = terrain::kTileVertexSeaOffset; k < mesh.vertices.size();
       k += terrain::kTileVertexFloats) {
    gpu.allLand = gpu.allLand && mesh.vertices[k] == 0.0f;
    gpu.allWater = gpu.allWater && mesh.vertices[k] == 1.0f;
  }
  std::vector<glm::dvec3> offsets;
  offsets.reserve(mesh.vertices.size() / terrain::kTileVertexFloats);
  for (size_t k = 0; k + terrain::kTileVertexFloats <= mesh.vertices.size();
       k += terrain::kTileVertexFloats) {
    const glm::dvec3 offset(mesh.vertices[k + terrain::kTileVertexPositionOffset],
                            mesh.vertices[k + terrain::kTileVertexPositionOffset + 1],
                            mesh.vertices[k + terrain::kTileVertexPositionOffset + 2]);
    radiusSquared = std::max(radiusSquared, glm::dot(offset, offset));
    offsets.push_back(offset);
  }
  gpu.radiusMeters = std::sqrt(radiusSquared);
  gpu.box = terrain::makeTileBox(mesh.centerEcefMeters, offsets);

  gpu.vertexArray = makeGlVertexArray();
  gpu.vertexBuffer = makeGlBuffer();
  glBindVertexArray(gpu.vertexArray.get());
  glBindBuffer(GL_ARRAY_BUFFER, gpu.vertexBuffer.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(gpu.vertexBytes), mesh.vertices.data(),
               GL_STATIC_DRAW);
  floatAttribute(kAttributeOffset, 3, terrain::kTileVertexPositionOffset);
  floatAttribute(kAttributeNormal, 3, terrain::kTileVertexNormalOffset);
  floatAttribute(kAttributeHeight, 1, terrain::kTileVertexHeightOffset);
  floatAttribute(kAttributeSea, 1, terrain::kTileVertexSeaOffset);
  floatAttribute(kAttributeUv, 2, terrain::kTileVertexUvOffset);
  floatAttribute(kAttributeCoarseNormal, 3, terrain::kTileVertexCoarseNormalOffset);
  if (!mesh.indices.empty()) {
    gpu.indexBuffer = makeGlBuffer();
    gpu.indexCount = static_cast<uint32_t>(mesh.indices.size());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indexBuffer.get());  // recorded in the vertex array
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);
    gpu.vertexBytes += mesh.indices.size() * sizeof(uint32_t);
  } else {
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer);  // recorded in the vertex array
  }
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  return gpu;
}

bool setGpuTileSunlight(GpuTile& gpu, std::span<const float> gridVisibility) {
  const uint32_t n = gpu.verticesPerSide;
  if (gridVisibility.size() != static_cast<size_t>(n) * n || gpu.indexCount > 0) return false;
  std::vector<float> values(terrain::tileVertexCount(n, gpu.hasSkirts), 1.0f);
  std::copy(gridVisibility.begin(), gridVisibility.end(), values.begin());
  for (uint32_t edge = 0; gpu.hasSkirts && edge < 4; ++edge) {
    for (uint32_t k = 0; k < n; ++k) {
      const auto side = static_cast<terrain::TileEdge>(edge);
      values[terrain::skirtVertexIndex(side, k, n)] =
          gridVisibility[terrain::edgeGridIndex(side, k, n)];
    }
  }
  if (!gpu.sunlightBuffer) gpu.sunlightBuffer = makeGlBuffer();
  glBindVertexArray(gpu.vertexArray.get());
  glBindBuffer(GL_ARRAY_BUFFER, gpu.sunlightBuffer.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(values.size() * sizeof(float)),
               values.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(kAttributeSunlight, 1, GL_FLOAT, GL_FALSE, sizeof(float), nullptr);
  glEnableVertexAttribArray(kAttributeSunlight);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  return true;
}

}  // namespace globe::render
