#include "terrain/tin_mesh.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "terrain/mesh_vertex.hpp"
#include "terrain/tin_tile.hpp"

namespace globe::terrain {
namespace {

// Mixed into a TIN tile's edge hashes: no grid tile's edge equals a TIN's.
constexpr uint64_t kTinEdgeSalt = 0x9e3779b97f4a7c15ULL;

glm::dvec3 upAt(const geo::Ellipsoid& ellipsoid, const glm::dvec3& ecef) {
  return geo::geodeticSurfaceNormal(ellipsoid, ecef);
}

// Per vertex, the area-weighted sum of its triangles' normals, turned up.
std::vector<glm::dvec3> derivedNormals(const TinTile& tin, const std::vector<MeshVertex>& v,
                                       const geo::Ellipsoid& ellipsoid) {
  std::vector<glm::dvec3> sum(tin.vertices().size(), glm::dvec3(0.0));
  const std::vector<uint32_t>& t = tin.triangles();
  for (size_t k = 0; k + 2 < t.size(); k += 3) {
    const glm::dvec3 n = glm::cross(v[t[k + 1]].positionEcef - v[t[k]].positionEcef,
                                    v[t[k + 2]].positionEcef - v[t[k]].positionEcef);
    const double sign = glm::dot(n, upAt(ellipsoid, v[t[k]].positionEcef)) < 0 ? -1.0 : 1.0;
    for (size_t c = 0; c < 3; ++c) sum[t[k + c]] += sign * n;
  }
  for (size_t k = 0; k < sum.size(); ++k) {
    const double length = glm::length(sum[k]);
    sum[k] =
        length > 0 && std::isfinite(length) ? sum[k] / length : upAt(ellipsoid, v[k].positionEcef);
  }
  return sum;
}

// The surface's triangles, counter-clockwise from above: positive area in (u east, v north).
void appendSurfaceTriangles(const TinTile& tin, std::vector<uint32_t>& indices) {
  const std::vector<TinVertex>& p = tin.vertices();
  const std::vector<uint32_t>& t = tin.triangles();
  for (size_t k = 0; k + 2 < t.size(); k += 3) {
    const TinVertex &a = p[t[k]], &b = p[t[k + 1]], &c = p[t[k + 2]];
    const double area = twiceSignedArea(a, b, c);
    if (area == 0) continue;
    indices.insert(indices.end(),
                   {t[k], area > 0 ? t[k + 1] : t[k + 2], area > 0 ? t[k + 2] : t[k + 1]});
  }
}

// The vertices on each edge (west, east, south, north), in order along it.
std::vector<std::vector<uint32_t>> edgeVertices(const TinTile& tin) {
  const std::vector<TinVertex>& p = tin.vertices();
  std::vector<std::vector<uint32_t>> edges(4);
  for (uint32_t k = 0; k < p.size(); ++k) {
    if (p[k].u == 0) edges[0].push_back(k);
    if (p[k].u == 1) edges[1].push_back(k);
    if (p[k].v == 0) edges[2].push_back(k);
    if (p[k].v == 1) edges[3].push_back(k);
  }
  for (size_t e = 0; e < 4; ++e) {
    const bool alongV = e < 2;
    std::sort(edges[e].begin(), edges[e].end(),
              [&](uint32_t a, uint32_t b) { return alongV ? p[a].v < p[b].v : p[a].u < p[b].u; });
  }
  return edges;
}

}  // namespace

TileMesh buildTinMesh(const geo::TileId& tile, const HeightBlock& block,
                      const geo::Ellipsoid& ellipsoid, double skirtDepthMeters) {
  const TinTile& tin = *block.tin;
  const uint32_t n = block.verticesPerSide;
  TileMesh mesh;
  mesh.verticesPerSide = n;
  mesh.hasSkirts = skirtDepthMeters > 0.0;
  mesh.edgeHeightHashes = edgeHeightHashes(block);
  for (uint64_t& hash : mesh.edgeHeightHashes) hash ^= kTinEdgeSalt;

  const double quantum = vertexQuantumMeters(tile.level);
  std::vector<MeshVertex> vertices(tin.vertices().size());
  for (uint32_t k = 0; k < vertices.size(); ++k) {
    const TinVertex& p = tin.vertices()[k];
    MeshVertex& v = vertices[k];
    v.positionEcef = tin.vertexEcefMeters(ellipsoid, k);
    v.heightMeters = v.colorHeightMeters = p.heightMeters;
    const auto row = static_cast<uint32_t>(std::lround((1.0 - p.v) * (n - 1)));
    const auto column = static_cast<uint32_t>(std::lround(p.u * (n - 1)));
    v.sea = n >= 2 && block.heights.size() == size_t{n} * n && isWater(block.at(row, column))
                ? 1.0f
                : 0.0f;
    v.u = static_cast<float>(p.u);
    v.v = static_cast<float>(1.0 - p.v);
  }
  const std::vector<glm::dvec3> derived =
      tin.normals().empty() ? derivedNormals(tin, vertices, ellipsoid) : std::vector<glm::dvec3>{};
  for (uint32_t k = 0; k < vertices.size(); ++k) {
    vertices[k].normal =
        derived.empty() ? glm::dvec3(glm::normalize(tin.normals()[k])) : derived[k];
    vertices[k].coarseNormal = vertices[k].normal;
  }
  appendSurfaceTriangles(tin, mesh.indices);

  if (mesh.hasSkirts) {
    const glm::dvec3 centre = geo::cartographicToEcef(
        ellipsoid, {0.5 * (tin.rectangle().westRadians + tin.rectangle().eastRadians),
                    0.5 * (tin.rectangle().southRadians + tin.rectangle().northRadians), 0.0});
    for (const std::vector<uint32_t>& edge : edgeVertices(tin)) {
      const auto first = static_cast<uint32_t>(vertices.size());
      for (uint32_t k : edge) {
        MeshVertex skirt = vertices[k];
        const glm::dvec3 up = upAt(ellipsoid, skirt.positionEcef);
        skirt.positionEcef -= skirtDepthMeters * up;
        vertices.push_back(skirt);
      }
      for (uint32_t k = 0; k + 1 < edge.size(); ++k) {
        const uint32_t a = edge[k], b = edge[k + 1], sa = first + k, sb = first + k + 1;
        // Counter-clockwise from outside: the quad's normal points away from the tile's centre.
        const glm::dvec3 out = vertices[a].positionEcef - centre;
        const glm::dvec3 normal = glm::cross(vertices[b].positionEcef - vertices[a].positionEcef,
                                             vertices[sa].positionEcef - vertices[a].positionEcef);
        if (glm::dot(normal, out) > 0) {
          mesh.indices.insert(mesh.indices.end(), {a, b, sa, b, sb, sa});
        } else {
          mesh.indices.insert(mesh.indices.end(), {a, sa, b, b, sa, sb});
        }
      }
    }
  }
  for (MeshVertex& v : vertices) v.positionEcef = quantizedEcefMeters(v.positionEcef, quantum);
  packMeshVertices(vertices, tile.level, mesh);
  return mesh;
}

}  // namespace globe::terrain
