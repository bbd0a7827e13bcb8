#include "tiles3d/loaded_content.hpp"

#include <map>
#include <set>
#include <tuple>

#include "tiles3d/tile_content.hpp"

namespace globe::tiles3d {

namespace {

// The mesh's triangles grouped by the surface they wear (instances and inner tiles repeat
// theirs: one part each).
DrawnContent drawnOf(const TriangleMesh& mesh) {
  DrawnContent drawn;
  if (!mesh.positions.empty()) drawn.originEcefMeters = mesh.positions[0];
  std::map<std::tuple<const MeshTexture*, float, float, float, float, float>, size_t> partOf;
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const SurfacePart surface =
        t < mesh.triangleParts.size() && mesh.triangleParts[t] < mesh.parts.size()
            ? mesh.parts[mesh.triangleParts[t]]
            : SurfacePart{};
    const glm::vec4& c = surface.baseColor;
    const auto [it, added] = partOf.try_emplace(
        {surface.texture.get(), c.r, c.g, c.b, c.a, surface.alphaCutoff}, drawn.parts.size());
    if (added) drawn.parts.push_back({{}, {}, {}, surface});
    DrawnPart& part = drawn.parts[it->second];
    for (size_t k = 3 * t; k < 3 * t + 3; ++k) {
      part.offsetsMeters.emplace_back(mesh.positions[k] - drawn.originEcefMeters);
      part.normals.push_back(k < mesh.normals.size() ? mesh.normals[k] : glm::vec3(0.0f));
      if (surface.texture) part.uvs.push_back(k < mesh.uvs.size() ? mesh.uvs[k] : glm::vec2(0.0f));
    }
  }
  return drawn;
}

}  // namespace

size_t LoadedContent::sizeBytes() const {
  size_t bytes = sizeof(LoadedContent) + grid.sizeBytes();
  std::set<const MeshTexture*> textures;
  for (const DrawnPart& part : drawn.parts) {
    bytes +=
        part.offsetsMeters.size() * sizeof(glm::vec3) * 2 + part.uvs.size() * sizeof(glm::vec2);
    if (part.surface.texture && textures.insert(part.surface.texture.get()).second)
      bytes += part.surface.texture->rgba.size();
  }
  return bytes;
}

Result<LoadedContent> loadContent(std::span<const std::byte> bytes, const glm::dmat4& tileTransform,
                                  const geo::Ellipsoid& ellipsoid, const std::string& name) {
  auto mesh = readTileContent(bytes, tileTransform, ellipsoid, name);
  if (!mesh) return Error{mesh.error()};
  LoadedContent content;
  content.triangleCount = mesh->triangleCount();
  content.grid =
      HeightGrid::rasterize(*mesh, ellipsoid, kHeightGridCellMeters, kMaxHeightGridCells);
  content.drawn = drawnOf(*mesh);
  return content;
}

Result<LoadedContent> loadTileContent(const Tileset& tileset, const TileNode& tile,
                                      const std::string& name, const geo::Ellipsoid& ellipsoid) {
  auto bytes = readContentBytes(tileset, name);
  if (!bytes) return Error{bytes.error()};
  return loadContent(*bytes, tile.transform, ellipsoid, tileset.source->locationOf(name));
}

}  // namespace globe::tiles3d
