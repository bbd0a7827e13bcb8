#include "terrain/upsampled_block.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"
#include "terrain/tin_clip.hpp"

namespace globe::terrain {
namespace {

// Floor of a / 2, for negative a too.
int halfFloor(int a) { return a >= 0 ? a / 2 : -((1 - a) / 2); }

int16_t meanSample(int16_t a, int16_t b) {
  if (isWater(a) && isWater(b)) return encodeWater(0.5 * (seaFloorMeters(a) + seaFloorMeters(b)));
  if (isWater(a) || isWater(b)) return a;
  return static_cast<int16_t>(std::lround(0.5 * (static_cast<double>(a) + b)));
}

// A vertex of a grid, in or around its tile: its place in degrees.
BlockGrid::Vertex placeOf(const BlockGrid& grid, int row, int column) {
  const auto last = static_cast<int>(grid.verticesPerSide) - 1;
  if (row >= 0 && row <= last && column >= 0 && column <= last) {
    return {grid.longitudeDegrees(static_cast<uint32_t>(column)),
            grid.latitudeDegrees(static_cast<uint32_t>(row))};
  }
  return grid.wrappedVertex(row, column);
}

// The parent's surface, read at (row, column) of its block or apron.
class ParentSurface {
 public:
  ParentSurface(const HeightBlock& block, const geo::TileId& tile, const geo::Ellipsoid& ellipsoid)
      : block_(block), grid_{tile, block.verticesPerSide}, ellipsoid_(ellipsoid) {}

  bool has(int row, int column) const {
    const auto last = static_cast<int>(block_.verticesPerSide) - 1;
    const int reach = block_.hasApron() ? kApronWidth : 0;
    return row >= -reach && row <= last + reach && column >= -reach && column <= last + reach;
  }
  double heightMeters(int row, int column) const {
    return block_.surfaceHeightMetersWithApron(row, column);
  }
  int16_t sample(int row, int column) const { return block_.atWithApron(row, column); }
  // Where the parent's mesh puts the vertex.
  glm::dvec3 ecefMeters(int row, int column) const {
    return levelVertexEcefMeters(ellipsoid_, grid_, row, column, heightMeters(row, column));
  }

 private:
  const HeightBlock& block_;
  BlockGrid grid_;
  const geo::Ellipsoid& ellipsoid_;
};

struct Point {
  double heightMeters;
  int16_t sample;
};

// Height along the ellipsoid normal at `place` of the plane through three vertices, as collision's
// exact surface reads a triangle; NaN where the normal runs along the plane (or at a pole).
double planeHeightMeters(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                         const BlockGrid::Vertex& place, const geo::Ellipsoid& ellipsoid) {
  if (std::abs(place.latitudeDegrees) == 90.0) return std::nan("");
  const auto where =
      geo::Cartographic::fromDegrees(place.longitudeDegrees, place.latitudeDegrees, 0.0);
  const glm::dvec3 ground = geo::cartographicToEcef(ellipsoid, where);
  const glm::dvec3 up = geo::geodeticSurfaceNormal(ellipsoid, where);
  const glm::dvec3 normal = glm::cross(b - a, c - a);
  const double along = glm::dot(normal, up);
  if (!(std::abs(along) > 1e-6 * glm::length(normal))) return std::nan("");
  return glm::dot(normal, a - ground) / along;
}

// The parent's surface at the point of twice-coordinates (rowTwice, columnTwice) (in half
// parent cells), at `place`: a parent vertex, or the middle of an edge of the parent's triangles
// (a row, a column, or a cell's north-west to south-east diagonal), where the ellipsoid normal
// meets the plane of the triangle the diagonal rule gives there (the diagonal goes to the
// south-west half): the exact surface collision reads.
Point onParentSurface(const ParentSurface& parent, int rowTwice, int columnTwice,
                      const BlockGrid::Vertex& place, const geo::Ellipsoid& ellipsoid) {
  const int row = halfFloor(rowTwice), column = halfFloor(columnTwice);
  const bool midRow = rowTwice != 2 * row, midColumn = columnTwice != 2 * column;
  if (!midRow && !midColumn) return {parent.heightMeters(row, column), parent.sample(row, column)};
  // The edge's two ends.
  const int endRow = row + (midRow ? 1 : 0), endColumn = column + (midColumn ? 1 : 0);
  const double meanMeters =
      0.5 * (parent.heightMeters(row, column) + parent.heightMeters(endRow, endColumn));
  const int16_t sample = meanSample(parent.sample(row, column), parent.sample(endRow, endColumn));
  // The triangle's third vertex: south-west half {(r,c), (r+1,c), (r+1,c+1)} for a column edge
  // and the diagonal, north-east half {(r,c), (r+1,c+1), (r,c+1)} for a row edge. At the border
  // of a block without apron, the other triangle on that edge.
  int thirdRow = row + 1, thirdColumn = column + 1;  // a column edge or a row edge
  if (midRow && midColumn) thirdColumn = column;     // the diagonal
  if (!parent.has(thirdRow, thirdColumn)) {
    if (!midColumn) {  // north-east half of the quad to the west
      thirdRow = row;
      thirdColumn = column - 1;
    } else if (!midRow) {  // south-west half of the quad to the north
      thirdRow = row - 1;
      thirdColumn = column;
    }
  }
  double height = std::nan("");
  if (parent.has(thirdRow, thirdColumn)) {
    height = planeHeightMeters(parent.ecefMeters(row, column), parent.ecefMeters(endRow, endColumn),
                               parent.ecefMeters(thirdRow, thirdColumn), place, ellipsoid);
  }
  return {std::isfinite(height) ? height : meanMeters, sample};
}

}  // namespace

HeightBlock upsampleBlock(const HeightBlock& parent, const geo::TileId& child,
                          const geo::Ellipsoid& ellipsoid) {
  const uint32_t n = parent.verticesPerSide;
  HeightBlock block;
  block.verticesPerSide = n;
  block.sea = parent.sea;
  // A TIN parent's child is its TIN's quadrant: the surface drawn and collided (tin_clip.hpp).
  if (parent.tin) block.tin = childTin(*parent.tin, child);
  const ParentSurface surface(parent, child.parent(), ellipsoid);
  const BlockGrid grid{child, n};
  const auto half = static_cast<int>(n - 1);  // a child spans half the parent: N-1 half cells
  const int rowOffset = (child.y & 1u) != 0 ? half : 0;
  const int columnOffset = (child.x & 1u) != 0 ? half : 0;
  auto at = [&](int row, int column) {
    return onParentSurface(surface, rowOffset + row, columnOffset + column,
                           placeOf(grid, row, column), ellipsoid);
  };
  block.heights.resize(static_cast<size_t>(n) * n);
  block.exactSurfaceMeters.resize(block.heights.size());
  for (uint32_t i = 0; i < n; ++i) {
    for (uint32_t j = 0; j < n; ++j) {
      const Point p = at(static_cast<int>(i), static_cast<int>(j));
      const size_t k = static_cast<size_t>(i) * n + j;
      block.heights[k] = p.sample;
      block.exactSurfaceMeters[k] = p.heightMeters;
    }
  }
  // The shading: the parent's vertex values, linear along its edges (the diagonal included), as
  // its triangles interpolate them. The normals are the parent mesh's, not the child's own: those
  // would show the parent's flat facets, with light and dark lines along their edges.
  const std::vector<glm::dvec3> parentNormals =
      gridVertexNormals(child.parent(), parent, ellipsoid);
  block.shadingNormals.resize(block.heights.size());
  block.colorMeters.resize(block.heights.size());
  block.waterFraction.resize(block.heights.size());
  auto parentIndex = [&](int row, int column) { return static_cast<size_t>(row) * n + column; };
  auto colorAt = [&](size_t k) {
    return parent.colorMeters.empty() ? static_cast<float>(seaFloorMeters(parent.heights[k]))
                                      : parent.colorMeters[k];
  };
  auto waterAt = [&](size_t k) {
    return parent.waterFraction.empty() ? (isWater(parent.heights[k]) ? 1.0f : 0.0f)
                                        : parent.waterFraction[k];
  };
  for (uint32_t i = 0; i < n; ++i) {
    for (uint32_t j = 0; j < n; ++j) {
      const int rowTwice = rowOffset + static_cast<int>(i);
      const int columnTwice = columnOffset + static_cast<int>(j);
      const int row = rowTwice / 2, column = columnTwice / 2;  // within the parent's grid
      const size_t a = parentIndex(row, column);
      const size_t b = parentIndex(row + rowTwice % 2, column + columnTwice % 2);
      const size_t k = static_cast<size_t>(i) * n + j;
      glm::dvec3 normal = parentNormals.size() > std::max(a, b)
                              ? parentNormals[a] + parentNormals[b]
                              : glm::dvec3(0.0);
      const double length = glm::length(normal);
      block.shadingNormals[k] = length > 0 ? glm::vec3(normal / length) : glm::vec3(0.0f);
      block.colorMeters[k] = 0.5f * (colorAt(a) + colorAt(b));
      block.waterFraction[k] = 0.5f * (waterAt(a) + waterAt(b));
    }
  }
  if (parentNormals.size() != block.heights.size()) block.shadingNormals.clear();
  if (!parent.hasApron()) return block;
  // The child's apron reaches kApronWidth child spacings (one parent spacing) past its edges:
  // inside the parent's block and apron.
  block.apron.resize(apronSampleCount(n));
  block.exactApronSurfaceMeters.resize(block.apron.size());
  const int last = static_cast<int>(n) - 1;
  for (int row = -kApronWidth; row <= last + kApronWidth; ++row) {
    for (int column = -kApronWidth; column <= last + kApronWidth; ++column) {
      if (row >= 0 && row <= last && column >= 0 && column <= last) continue;
      const Point p = at(row, column);
      const size_t k = apronIndex(row, column, n);
      block.apron[k] = p.sample;
      block.exactApronSurfaceMeters[k] = p.heightMeters;
    }
  }
  return block;
}

}  // namespace globe::terrain
