#include "tiles3d/loaded_content.hpp"

#include "tiles3d/tile_content.hpp"

namespace globe::tiles3d {

size_t LoadedContent::sizeBytes() const {
  return sizeof(LoadedContent) + drawn.offsetsMeters.size() * sizeof(glm::vec3) + grid.sizeBytes();
}

Result<LoadedContent> loadContent(std::span<const std::byte> bytes, const glm::dmat4& tileTransform,
                                  const geo::Ellipsoid& ellipsoid, const std::string& name) {
  auto mesh = readTileContent(bytes, tileTransform, ellipsoid, name);
  if (!mesh) return Error{mesh.error()};
  LoadedContent content;
  content.triangleCount = mesh->triangleCount();
  content.grid =
      HeightGrid::rasterize(*mesh, ellipsoid, kHeightGridCellMeters, kMaxHeightGridCells);
  DrawnContent& drawn = content.drawn;
  if (!mesh->positions.empty()) drawn.originEcefMeters = mesh->positions[0];
  drawn.offsetsMeters.reserve(mesh->positions.size());
  for (const glm::dvec3& p : mesh->positions) {
    drawn.offsetsMeters.emplace_back(p - drawn.originEcefMeters);
  }
  return content;
}

}  // namespace globe::tiles3d
