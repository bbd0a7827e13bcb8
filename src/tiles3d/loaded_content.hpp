// One 3D tile content as the viewer keeps it once loaded: its triangles as drawn (float offsets
// from an origin of its own) and its highest surface as a height grid (height_grid.hpp) that
// collision reads in O(1). Made on a loader thread; immutable after.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "tiles3d/height_grid.hpp"
#include "tiles3d/tileset.hpp"
#include "tiles3d/triangle_mesh.hpp"

namespace globe::tiles3d {

// Grid cells of about this size (m), at most this many a side.
inline constexpr double kHeightGridCellMeters = 0.5;
inline constexpr uint32_t kMaxHeightGridCells = 512;

// The triangles of a content that wear one surface (a base colour, a texture or none).
struct DrawnPart {
  std::vector<glm::vec3> offsetsMeters;  // three per triangle, from the content's origin
  std::vector<glm::vec3> normals;        // per corner; zero: the triangle's own made where drawn
  std::vector<glm::vec2> uvs;            // per corner (with a texture)
  SurfacePart surface;
};

// A content as drawn: float offsets from an origin of its own (its first vertex).
struct DrawnContent {
  glm::dvec3 originEcefMeters{0.0};
  std::vector<DrawnPart> parts;
};

struct LoadedContent {
  DrawnContent drawn;
  HeightGrid grid;
  size_t triangleCount = 0;
  size_t sizeBytes() const;  // what it holds in memory, for the cache's budget
};

// Errors name `name` (the file or URL) and say what is wrong.
Result<LoadedContent> loadContent(std::span<const std::byte> bytes, const glm::dmat4& tileTransform,
                                  const geo::Ellipsoid& ellipsoid, const std::string& name);

// A tile's content `name` read from its tileset's source and loaded as above; errors name its
// file or URL.
Result<LoadedContent> loadTileContent(const Tileset& tileset, const TileNode& tile,
                                      const std::string& name, const geo::Ellipsoid& ellipsoid);

}  // namespace globe::tiles3d
