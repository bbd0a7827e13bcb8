// A TIN tile's mesh (terrain/tin_mesh.hpp) over a real quantized-mesh tile: the file's vertices
// where its heights put them, every surface triangle facing up, every skirt triangle facing out of
// the tile, skirts hanging from each edge vertex, and its edges never mistaken for a grid's.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

#include <glm/geometric.hpp>

#include "formats/quantized_mesh.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/tile_mesh.hpp"
#include "terrain/tin_tile.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/quantized_mesh_file.hpp"

namespace globe::terrain {
namespace {

namespace fs = std::filesystem;

HeightBlock tinBlock(const geo::TileId& id, const fs::path& path) {
  auto mesh = globe::testing::readQuantizedMeshFile(path);
  EXPECT_TRUE(mesh) << mesh.error();
  auto tin = TinTile::build(geo::GeographicTilingScheme::tileRectangle(id),
                            globe::testing::tinVertices(*mesh), mesh->triangles, path.string());
  EXPECT_TRUE(tin) << tin.error();
  HeightBlock block;
  block.verticesPerSide = 65;
  block.heights.assign(65 * 65, 0);
  block.tin = std::make_shared<const TinTile>(std::move(*tin));
  return block;
}

glm::dvec3 positionOf(const TileMesh& mesh, uint32_t k) {
  const float* v = &mesh.vertices[size_t{k} * kTileVertexFloats + kTileVertexPositionOffset];
  return mesh.centerEcefMeters + glm::dvec3(v[0], v[1], v[2]);
}

TEST(TinMesh, SurfaceFacesUpAndSkirtsFaceOutOfTheTile) {
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  const geo::TileId id{15, 33550, 32767 - 25865};
  const HeightBlock block = tinBlock(
      id, fs::path(GLOBE_SOURCE_DIR) /
              "tests/data/interop/quantized-mesh/denhaag-ahn-octnormals/15/33550/25865.terrain");
  const TinTile& tin = *block.tin;
  const TileMesh mesh = buildTileMesh(id, block, wgs84, 50.0);
  ASSERT_FALSE(mesh.indices.empty());
  // The file's vertices first, where its heights put them (within the level's rounding).
  for (uint32_t k = 0; k < tin.vertices().size(); ++k) {
    EXPECT_LT(glm::distance(positionOf(mesh, k), tin.vertexEcefMeters(wgs84, k)), 0.01);
  }
  const geo::GlobeRectangle r = tin.rectangle();
  const glm::dvec3 centre = geo::cartographicToEcef(
      wgs84, {0.5 * (r.westRadians + r.eastRadians), 0.5 * (r.southRadians + r.northRadians), 0});
  const glm::dvec3 up = geo::geodeticSurfaceNormal(wgs84, centre);
  // The mesh leaves out triangles of no area (the file has some): the surface's come first.
  size_t surfaceTriangles = 0;
  for (size_t t = 0; t + 2 < tin.triangles().size(); t += 3) {
    const TinVertex &a = tin.vertices()[tin.triangles()[t]],
                    &b = tin.vertices()[tin.triangles()[t + 1]],
                    &c = tin.vertices()[tin.triangles()[t + 2]];
    surfaceTriangles += (b.u - a.u) * (c.v - a.v) - (c.u - a.u) * (b.v - a.v) != 0 ? 1 : 0;
  }
  size_t surface = 0, skirts = 0;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a = positionOf(mesh, mesh.indices[t]),
                     b = positionOf(mesh, mesh.indices[t + 1]),
                     c = positionOf(mesh, mesh.indices[t + 2]);
    const glm::dvec3 normal = glm::cross(b - a, c - a);
    if (t / 3 < surfaceTriangles) {
      EXPECT_GT(glm::dot(normal, up), 0.0) << "surface triangle " << t / 3;
      ++surface;
    } else {
      const glm::dvec3 mid = (a + b + c) / 3.0;
      const glm::dvec3 out = (mid - centre) - glm::dot(mid - centre, up) * up;  // horizontal
      EXPECT_GT(glm::dot(normal, out), 0.0) << "skirt triangle " << t / 3;
      ++skirts;
    }
  }
  EXPECT_EQ(surface, surfaceTriangles);
  EXPECT_GT(surface, tin.triangleCount() / 2);
  EXPECT_GE(skirts, 8u);  // two a segment, at least one segment an edge
  // A TIN's edge hashes are never a grid's: a grid neighbour draws its skirt.
  EXPECT_NE(mesh.edgeHeightHashes, edgeHeightHashes(block));
}

}  // namespace
}  // namespace globe::terrain
