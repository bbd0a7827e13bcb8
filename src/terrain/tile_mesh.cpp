// Builds tile meshes (double ECEF → float offsets, normals, skirts) and the shared index buffer.
#include "terrain/tile_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "terrain/mesh_vertex.hpp"
#include "terrain/tin_mesh.hpp"

namespace globe::terrain {
namespace {

// ECEF of a grid vertex; latitude ±90° lands exactly on the polar axis.
glm::dvec3 vertexEcef(const geo::Ellipsoid& ellipsoid, double longitudeDegrees,
                      double latitudeDegrees, double heightMeters) {
  if (std::abs(latitudeDegrees) == 90.0) {
    const auto pole = geo::Cartographic::fromDegrees(0.0, latitudeDegrees, heightMeters);
    return {0.0, 0.0, geo::cartographicToEcef(ellipsoid, pole).z};
  }
  return geo::cartographicToEcef(
      ellipsoid, geo::Cartographic::fromDegrees(longitudeDegrees, latitudeDegrees, heightMeters));
}

glm::dvec3 ellipsoidNormal(const geo::Ellipsoid& ellipsoid, double longitudeDegrees,
                           double latitudeDegrees) {
  if (std::abs(latitudeDegrees) == 90.0) return {0.0, 0.0, latitudeDegrees > 0 ? 1.0 : -1.0};
  return geo::geodeticSurfaceNormal(
      ellipsoid, geo::Cartographic::fromDegrees(longitudeDegrees, latitudeDegrees, 0.0));
}

using Vertex = MeshVertex;

}  // namespace

glm::dvec3 tileVertexEcefMeters(const geo::Ellipsoid& ellipsoid, const BlockGrid& grid,
                                uint32_t row, uint32_t column, double heightMeters) {
  return vertexEcef(ellipsoid, grid.longitudeDegrees(column), grid.latitudeDegrees(row),
                    heightMeters);
}

glm::dvec3 levelVertexEcefMeters(const geo::Ellipsoid& ellipsoid, const BlockGrid& grid, int row,
                                 int column, double heightMeters) {
  const auto last = static_cast<int>(grid.verticesPerSide) - 1;
  if (row >= 0 && row <= last && column >= 0 && column <= last) {
    return tileVertexEcefMeters(ellipsoid, grid, static_cast<uint32_t>(row),
                                static_cast<uint32_t>(column), heightMeters);
  }
  const BlockGrid::Vertex where = grid.wrappedVertex(row, column);
  return vertexEcef(ellipsoid, where.longitudeDegrees, where.latitudeDegrees, heightMeters);
}

double vertexQuantumMeters(uint32_t level) {
  return std::ldexp(kLevelZeroVertexQuantumMeters, -static_cast<int>(level));
}

double originQuantumMeters(uint32_t level) {
  return kOriginQuantumPerVertexQuantum * vertexQuantumMeters(level);
}

glm::dvec3 quantizedEcefMeters(const glm::dvec3& position, double quantumMeters) {
  // Division and multiplication by a power of two are exact; only the rounding rounds.
  return glm::dvec3(std::nearbyint(position.x / quantumMeters),
                    std::nearbyint(position.y / quantumMeters),
                    std::nearbyint(position.z / quantumMeters)) *
         quantumMeters;
}

glm::dvec3 drawnVertexEcefMeters(const geo::Ellipsoid& ellipsoid, const BlockGrid& grid,
                                 uint32_t row, uint32_t column, double heightMeters) {
  return quantizedEcefMeters(tileVertexEcefMeters(ellipsoid, grid, row, column, heightMeters),
                             vertexQuantumMeters(grid.tile.level));
}

TileMesh buildTileMesh(const geo::TileId& tile, const HeightBlock& block,
                       const geo::Ellipsoid& ellipsoid, double skirtDepthMeters) {
  if (block.tin) return buildTinMesh(tile, block, ellipsoid, skirtDepthMeters);
  const uint32_t n = block.verticesPerSide;
  TileMesh mesh;
  mesh.verticesPerSide = n;
  mesh.hasSkirts = skirtDepthMeters > 0.0;
  if (!isValidBlockSize(n) || block.heights.size() != static_cast<size_t>(n) * n) return mesh;
  mesh.edgeHeightHashes = edgeHeightHashes(block);

  const BlockGrid grid{tile, n};
  std::vector<double> longitudes(n), latitudes(n);
  for (uint32_t k = 0; k < n; ++k) {
    longitudes[k] = grid.longitudeDegrees(k);
    latitudes[k] = grid.latitudeDegrees(k);
  }
  const float cells = static_cast<float>(n - 1);

  std::vector<Vertex> vertices(tileVertexCount(n, mesh.hasSkirts));
  for (uint32_t i = 0; i < n; ++i) {
    for (uint32_t j = 0; j < n; ++j) {
      const int16_t sample = block.at(i, j);
      Vertex& vertex = vertices[gridVertexIndex(i, j, n)];
      vertex.heightMeters = block.surfaceHeightMetersAt(i, j);
      const size_t k = static_cast<size_t>(i) * n + j;
      vertex.colorHeightMeters =
          block.colorMeters.empty() ? seaFloorMeters(sample) : block.colorMeters[k];
      vertex.positionEcef = vertexEcef(ellipsoid, longitudes[j], latitudes[i], vertex.heightMeters);
      vertex.sea =
          block.waterFraction.empty() ? (isWater(sample) ? 1.0f : 0.0f) : block.waterFraction[k];
      vertex.u = static_cast<float>(j) / cells;
      vertex.v = static_cast<float>(i) / cells;
    }
  }

  // Normals: central differences, across the edges too with the apron (the neighbours' vertices,
  // so both tiles compute the same normal for a shared edge vertex); one-sided on the edges of a
  // block without one.
  const bool apron = block.hasApron();
  const auto last = static_cast<int>(n) - 1;
  auto at = [&](int row, int column) {
    if (row >= 0 && row <= last && column >= 0 && column <= last) {
      return vertices[gridVertexIndex(static_cast<uint32_t>(row), static_cast<uint32_t>(column), n)]
          .positionEcef;
    }
    return levelVertexEcefMeters(ellipsoid, grid, row, column,
                                 block.surfaceHeightMetersWithApron(row, column));
  };
  // The normal at (row, column) from neighbours `step` vertices away: 1 for this level's, 2 for
  // the next coarser level's (every other vertex is its). Never past the apron.
  auto normalAt = [&](int row, int column, int step) {
    const int reach = apron ? step : 0;  // how far past the edge a difference may look
    const glm::dvec3 towardsSouth =
        at(std::min(row + step, last + reach), column) - at(std::max(row - step, -reach), column);
    const glm::dvec3 towardsEast =
        at(row, std::min(column + step, last + reach)) - at(row, std::max(column - step, -reach));
    const glm::dvec3 cross = glm::cross(towardsSouth, towardsEast);
    const glm::dvec3 up = ellipsoidNormal(ellipsoid, longitudes[static_cast<size_t>(column)],
                                          latitudes[static_cast<size_t>(row)]);
    const double length = glm::length(cross);
    const double scale = glm::length(towardsSouth) * glm::length(towardsEast);
    if (std::isfinite(length) && length > 1e-12 * scale && length > 0.0) {
      const glm::dvec3 candidate = cross / length;
      if (glm::dot(candidate, up) > 0.0) return candidate;
    }
    return up;
  };
  const bool ownShading = block.shadingNormals.size() == static_cast<size_t>(n) * n;
  for (uint32_t i = 0; i < n; ++i) {
    for (uint32_t j = 0; j < n; ++j) {
      Vertex& vertex = vertices[gridVertexIndex(i, j, n)];
      vertex.normal = ownShading ? glm::dvec3(block.shadingNormals[static_cast<size_t>(i) * n + j])
                                 : normalAt(static_cast<int>(i), static_cast<int>(j), 1);
      vertex.coarseNormal = vertex.normal;
    }
  }
  // Edge vertices also carry the next coarser level's normal there: the coarser mesh's own at its
  // vertices (every other one), and between them the mean of the two, as the coarser tile's edge
  // interpolates them. The renderer lights an edge with it where the neighbour is coarser.
  auto coarseAt = [&](int row, int column) { return normalAt(row, column, 2); };
  for (uint32_t i = 0; i < n && !ownShading; ++i) {
    for (uint32_t j = 0; j < n; ++j) {
      if (i != 0 && i != n - 1 && j != 0 && j != n - 1) continue;
      const auto row = static_cast<int>(i), column = static_cast<int>(j);
      glm::dvec3 coarse;
      if (row % 2 == 0 && column % 2 == 0) {
        coarse = coarseAt(row, column);
      } else if (row % 2 == 0) {  // on the north or south edge, between two coarser vertices
        coarse = glm::normalize(coarseAt(row, column - 1) + coarseAt(row, column + 1));
      } else {  // on the west or east edge
        coarse = glm::normalize(coarseAt(row - 1, column) + coarseAt(row + 1, column));
      }
      vertices[gridVertexIndex(i, j, n)].coarseNormal = coarse;
    }
  }

  // Vertices are drawn at the level's quantum (drawnVertexEcefMeters); the normals above come
  // from the exact grid.
  const double quantum = vertexQuantumMeters(tile.level);
  for (uint32_t k = 0; k < n * n; ++k) {
    vertices[k].positionEcef = quantizedEcefMeters(vertices[k].positionEcef, quantum);
  }

  if (mesh.hasSkirts) {
    for (uint32_t edge = 0; edge < 4; ++edge) {
      for (uint32_t k = 0; k < n; ++k) {
        const uint32_t index = edgeGridIndex(static_cast<TileEdge>(edge), k, n);
        Vertex skirt = vertices[index];
        skirt.positionEcef = drawnVertexEcefMeters(ellipsoid, grid, index / n, index % n,
                                                   skirt.heightMeters - skirtDepthMeters);
        vertices[skirtVertexIndex(static_cast<TileEdge>(edge), k, n)] = skirt;
      }
    }
  }

  packMeshVertices(vertices, tile.level, mesh);
  return mesh;
}

void packMeshVertices(const std::vector<MeshVertex>& vertices, uint32_t level, TileMesh& mesh) {
  glm::dvec3 lo(std::numeric_limits<double>::max());
  glm::dvec3 hi(std::numeric_limits<double>::lowest());
  for (const Vertex& vertex : vertices) {
    lo = glm::min(lo, vertex.positionEcef);
    hi = glm::max(hi, vertex.positionEcef);
  }
  // On the quantum too: the float offsets are then exact (tile_mesh.hpp).
  mesh.centerEcefMeters = quantizedEcefMeters(0.5 * (lo + hi), originQuantumMeters(level));

  mesh.vertices.reserve(vertices.size() * kTileVertexFloats);
  for (const Vertex& vertex : vertices) {
    const glm::dvec3 offset = vertex.positionEcef - mesh.centerEcefMeters;
    for (int c = 0; c < 3; ++c) mesh.vertices.push_back(static_cast<float>(offset[c]));
    for (int c = 0; c < 3; ++c) mesh.vertices.push_back(static_cast<float>(vertex.normal[c]));
    mesh.vertices.push_back(static_cast<float>(vertex.colorHeightMeters));
    mesh.vertices.push_back(vertex.sea);
    mesh.vertices.push_back(vertex.u);
    mesh.vertices.push_back(vertex.v);
    for (int c = 0; c < 3; ++c) mesh.vertices.push_back(static_cast<float>(vertex.coarseNormal[c]));
  }
}

double recommendedSkirtDepthMeters(uint32_t level, uint32_t verticesPerSide,
                                   const geo::Ellipsoid& ellipsoid) {
  const double a = ellipsoid.semiMajorAxisMeters;
  const double spacingRadians = geo::degreesToRadians(vertexSpacingDegrees(level, verticesPerSide));
  const double coarseSpacingMeters = 2.0 * spacingRadians * a;
  return coarseSpacingMeters * coarseSpacingMeters / (8.0 * a) +
         std::min(coarseSpacingMeters, 9000.0);
}

std::vector<uint32_t> buildGridIndices(uint32_t verticesPerSide, bool withSkirts) {
  const uint32_t n = verticesPerSide;
  std::vector<uint32_t> indices;
  if (n < 2) return indices;
  indices.reserve(static_cast<size_t>(n - 1) * (n - 1) * 6 + (withSkirts ? 24 * (n - 1) : 0));
  for (uint32_t i = 0; i + 1 < n; ++i) {
    for (uint32_t j = 0; j + 1 < n; ++j) {
      const uint32_t a = gridVertexIndex(i, j, n), b = gridVertexIndex(i, j + 1, n);
      const uint32_t c = gridVertexIndex(i + 1, j, n), d = gridVertexIndex(i + 1, j + 1, n);
      indices.insert(indices.end(), {a, c, d, a, d, b});
    }
  }
  if (!withSkirts) return indices;
  for (uint32_t edge = 0; edge < 4; ++edge) {
    const auto side = static_cast<TileEdge>(edge);
    for (uint32_t k = 0; k + 1 < n; ++k) {
      uint32_t e0 = 0, e1 = 0;
      switch (side) {
        case TileEdge::North:
          e0 = gridVertexIndex(0, k, n), e1 = gridVertexIndex(0, k + 1, n);
          break;
        case TileEdge::South:
          e0 = gridVertexIndex(n - 1, k, n), e1 = gridVertexIndex(n - 1, k + 1, n);
          break;
        case TileEdge::West:
          e0 = gridVertexIndex(k, 0, n), e1 = gridVertexIndex(k + 1, 0, n);
          break;
        case TileEdge::East:
          e0 = gridVertexIndex(k, n - 1, n), e1 = gridVertexIndex(k + 1, n - 1, n);
          break;
      }
      const uint32_t s0 = skirtVertexIndex(side, k, n), s1 = skirtVertexIndex(side, k + 1, n);
      // Seen from outside, k grows to the viewer's left on the north and east edges and to the
      // right on the south and west edges; both orders below are counter-clockwise from outside.
      if (side == TileEdge::North || side == TileEdge::East) {
        indices.insert(indices.end(), {e0, s1, s0, e0, e1, s1});
      } else {
        indices.insert(indices.end(), {e0, s0, s1, e0, s1, e1});
      }
    }
  }
  return indices;
}

std::vector<glm::dvec3> gridVertexNormals(const geo::TileId& tile, const HeightBlock& block,
                                          const geo::Ellipsoid& ellipsoid) {
  std::vector<glm::dvec3> normals;
  const size_t count = static_cast<size_t>(block.verticesPerSide) * block.verticesPerSide;
  if (block.shadingNormals.size() == count) {  // a block made from its parent's: its own
    normals.assign(block.shadingNormals.begin(), block.shadingNormals.end());
    return normals;
  }
  const TileMesh mesh = buildTileMesh(tile, block, ellipsoid, 0.0);
  if (mesh.vertices.size() < count * kTileVertexFloats) return normals;
  normals.reserve(count);
  for (size_t k = 0; k < count; ++k) {
    const float* v = &mesh.vertices[k * kTileVertexFloats + kTileVertexNormalOffset];
    normals.emplace_back(v[0], v[1], v[2]);
  }
  return normals;
}

}  // namespace globe::terrain
