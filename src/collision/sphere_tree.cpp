// Building the per-tile sphere trees (packed, pointer-free) and the first-hit sphere query.
#include "collision/sphere_tree.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"

namespace globe::collision {
namespace {

// Spheres are widened by this much (relative and absolute) so that rounding in the query's
// distances can never drop a triangle: ECEF coordinates carry ~1e-9 m of rounding.
constexpr double kRadiusRelativeMargin = 1e-12;
constexpr double kRadiusAbsoluteMarginMeters = 1e-6;
// Triangles whose sine of the angle at a is below 1e-6 are treated as segments.
constexpr double kDegenerateSineSquared = 1e-12;

uint64_t nodesUpToLevel(uint32_t depth) {  // 1 + 4 + ... + 4^depth
  return ((uint64_t{1} << (2 * (depth + 1))) - 1) / 3;
}
uint64_t firstNodeOfLevel(uint32_t level) { return ((uint64_t{1} << (2 * level)) - 1) / 3; }

// The even bits of a Morton index, packed.
uint32_t compactEvenBits(uint32_t value) {
  value &= 0x55555555u;
  value = (value | (value >> 1)) & 0x33333333u;
  value = (value | (value >> 2)) & 0x0f0f0f0fu;
  value = (value | (value >> 4)) & 0x00ff00ffu;
  value = (value | (value >> 8)) & 0x0000ffffu;
  return value;
}

double squaredLength(const glm::dvec3& v) { return glm::dot(v, v); }

double squaredDistanceToSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double length = glm::dot(ab, ab);
  const double t = length > 0.0 ? std::clamp(glm::dot(p - a, ab) / length, 0.0, 1.0) : 0.0;
  return squaredLength(p - (a + t * ab));
}

}  // namespace

double squaredDistanceToTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                 const glm::dvec3& c) {
  // Voronoi regions of the vertices, then the edges, then the face.
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return squaredLength(ap);
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return squaredLength(bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 && d1 - d3 > 0.0) {
    return squaredLength(p - (a + (d1 / (d1 - d3)) * ab));
  }
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return squaredLength(cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 && d2 - d6 > 0.0) {
    return squaredLength(p - (a + (d2 / (d2 - d6)) * ac));
  }
  const double va = d3 * d6 - d5 * d4;
  const double e1 = d4 - d3, e2 = d5 - d6;
  if (va <= 0.0 && e1 >= 0.0 && e2 >= 0.0 && e1 + e2 > 0.0) {
    return squaredLength(p - (b + (e1 / (e1 + e2)) * (c - b)));
  }
  // The face. va + vb + vc = |ab x ac|^2: (nearly) zero for a degenerate triangle (collinear or
  // collapsed, like half of a pole quad), whose closest point is then on its edges.
  const double sum = va + vb + vc;
  if (!(sum > kDegenerateSineSquared * glm::dot(ab, ab) * glm::dot(ac, ac))) {
    return std::min({squaredDistanceToSegment(p, a, b), squaredDistanceToSegment(p, b, c),
                     squaredDistanceToSegment(p, c, a)});
  }
  const double v = vb / sum, w = vc / sum;
  return squaredLength(p - (a + v * ab + w * ac));
}

void SphereTreeSet::build(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid) {
  const auto tiles = array.tiles();
  tiles_.clear();
  tiles_.reserve(tiles.size());
  uint64_t nodeCount = 0, vertexCount = 0;
  for (const ArrayTile& tile : tiles) {
    const uint32_t n = tile.block->verticesPerSide;
    const auto depth = static_cast<uint32_t>(std::countr_zero(n - 1));
    tiles_.push_back({nodeCount, vertexCount, n, depth});
    nodeCount += nodesUpToLevel(depth);
    vertexCount += uint64_t{n} * n;
  }
  nodes_.assign(nodeCount, BoundingSphere{});
  vertices_.assign(vertexCount, glm::dvec3{0.0});
  rootX_.assign(tiles.size(), 0.0);
  rootY_.assign(tiles.size(), 0.0);
  rootZ_.assign(tiles.size(), 0.0);
  rootRadius_.assign(tiles.size(), 0.0);

  for (uint32_t t = 0; t < tiles.size(); ++t) {
    const ArrayTile& tile = tiles[t];
    const TileTree& tree = tiles_[t];
    const uint32_t n = tree.verticesPerSide;
    const terrain::BlockGrid grid{tile.id, n};
    glm::dvec3* vertices = &vertices_[tree.firstVertex];
    for (uint32_t i = 0; i < n; ++i) {
      for (uint32_t j = 0; j < n; ++j) {
        vertices[size_t{i} * n + j] = terrain::tileVertexEcefMeters(
            ellipsoid, grid, i, j, tile.block->surfaceHeightMetersAt(i, j));
      }
    }
    for (uint32_t level = 0; level <= tree.depth; ++level) {
      for (uint32_t index = 0; index < (1u << (2 * level)); ++index) {
        const Block block = nodeBlock(t, level, index);
        glm::dvec3 low(HUGE_VAL), high(-HUGE_VAL);
        for (uint32_t i = block.firstRow; i <= block.firstRow + block.quadsPerSide; ++i) {
          for (uint32_t j = block.firstColumn; j <= block.firstColumn + block.quadsPerSide; ++j) {
            low = glm::min(low, vertices[size_t{i} * n + j]);
            high = glm::max(high, vertices[size_t{i} * n + j]);
          }
        }
        const glm::dvec3 center = 0.5 * (low + high);
        double radiusSquared = 0.0;
        for (uint32_t i = block.firstRow; i <= block.firstRow + block.quadsPerSide; ++i) {
          for (uint32_t j = block.firstColumn; j <= block.firstColumn + block.quadsPerSide; ++j) {
            radiusSquared =
                std::max(radiusSquared, squaredLength(vertices[size_t{i} * n + j] - center));
          }
        }
        const double radius =
            std::sqrt(radiusSquared) * (1.0 + kRadiusRelativeMargin) + kRadiusAbsoluteMarginMeters;
        nodes_[tree.firstNode + firstNodeOfLevel(level) + index] = {center, radius};
      }
    }
    const BoundingSphere& root = nodes_[tree.firstNode];
    rootX_[t] = root.centerEcefMeters.x;
    rootY_[t] = root.centerEcefMeters.y;
    rootZ_[t] = root.centerEcefMeters.z;
    rootRadius_[t] = root.radiusMeters;
  }
}

glm::dvec3 SphereTreeSet::vertex(uint32_t tile, uint32_t row, uint32_t column) const {
  const TileTree& tree = tiles_[tile];
  return vertices_[tree.firstVertex + size_t{row} * tree.verticesPerSide + column];
}

BoundingSphere SphereTreeSet::node(uint32_t tile, uint32_t level, uint32_t index) const {
  return nodes_[tiles_[tile].firstNode + firstNodeOfLevel(level) + index];
}

SphereTreeSet::Block SphereTreeSet::nodeBlock(uint32_t tile, uint32_t level, uint32_t index) const {
  const uint32_t quads = 1u << (tiles_[tile].depth - level);
  return {compactEvenBits(index >> 1) * quads, compactEvenBits(index) * quads, quads};
}

template <bool kFirstHitOnly>
bool SphereTreeSet::descend(uint32_t tile, uint32_t level, uint32_t index, const glm::dvec3& center,
                            double radius, SphereTreeResult& result,
                            std::vector<TriangleRef>* found) const {
  const TileTree& tree = tiles_[tile];
  if (level > 0) {  // the root was tested by the caller
    const BoundingSphere& sphere = nodes_[tree.firstNode + firstNodeOfLevel(level) + index];
    ++result.sphereTests;
    const double reach = sphere.radiusMeters + radius;
    if (!(squaredLength(sphere.centerEcefMeters - center) <= reach * reach)) return false;
  }
  if (level < tree.depth) {
    for (uint32_t child = 0; child < 4; ++child) {
      if (descend<kFirstHitOnly>(tile, level + 1, 4 * index + child, center, radius, result,
                                 found)) {
        return true;
      }
    }
    return false;
  }
  // A leaf: quad (i, j) and its two triangles, SW {(i,j), (i+1,j), (i+1,j+1)} and
  // NE {(i,j), (i+1,j+1), (i,j+1)}.
  const uint32_t i = compactEvenBits(index >> 1), j = compactEvenBits(index);
  const uint32_t n = tree.verticesPerSide;
  const glm::dvec3* v = &vertices_[tree.firstVertex + size_t{i} * n + j];
  const glm::dvec3 &a = v[0], &b = v[n], &c = v[n + 1], &d = v[1];
  const double radiusSquared = radius * radius;
  for (const bool southWest : {true, false}) {
    ++result.triangleTests;
    const double distance = southWest ? squaredDistanceToTriangle(center, a, b, c)
                                      : squaredDistanceToTriangle(center, a, c, d);
    if (distance <= radiusSquared) {
      const TriangleRef hit{tile, i, j, southWest};
      if (!result.collided) result.hit = hit;
      result.collided = true;
      if (kFirstHitOnly) return true;
      found->push_back(hit);
    }
  }
  return false;
}

SphereTreeResult SphereTreeSet::intersect(const glm::dvec3& center, double radius) const {
  SphereTreeResult result;
  const size_t count = rootX_.size();
  const double* x = rootX_.data();
  const double* y = rootY_.data();
  const double* z = rootZ_.data();
  const double* r = rootRadius_.data();
  for (size_t t = 0; t < count; ++t) {
    const double dx = x[t] - center.x, dy = y[t] - center.y, dz = z[t] - center.z;
    const double reach = r[t] + radius;
    if (dx * dx + dy * dy + dz * dz <= reach * reach &&
        descend<true>(static_cast<uint32_t>(t), 0, 0, center, radius, result, nullptr)) {
      result.sphereTests += static_cast<uint32_t>(t + 1);
      return result;
    }
  }
  result.sphereTests += static_cast<uint32_t>(count);
  return result;
}

SphereTreeResult SphereTreeSet::intersectTile(uint32_t tile, const glm::dvec3& center,
                                              double radius) const {
  SphereTreeResult result;
  result.sphereTests = 1;
  const double reach = rootRadius_[tile] + radius;
  const glm::dvec3 root{rootX_[tile], rootY_[tile], rootZ_[tile]};
  if (squaredLength(root - center) <= reach * reach) {
    descend<true>(tile, 0, 0, center, radius, result, nullptr);
  }
  return result;
}

std::vector<TriangleRef> SphereTreeSet::trianglesWithin(const glm::dvec3& center,
                                                        double radius) const {
  std::vector<TriangleRef> found;
  SphereTreeResult result;
  for (uint32_t t = 0; t < tiles_.size(); ++t) {
    const double reach = rootRadius_[t] + radius;
    const glm::dvec3 root{rootX_[t], rootY_[t], rootZ_[t]};
    if (squaredLength(root - center) <= reach * reach) {
      descend<false>(t, 0, 0, center, radius, result, &found);
    }
  }
  return found;
}

size_t SphereTreeSet::memoryBytes() const {
  return (rootX_.capacity() + rootY_.capacity() + rootZ_.capacity() + rootRadius_.capacity()) *
             sizeof(double) +
         tiles_.capacity() * sizeof(TileTree) + nodes_.capacity() * sizeof(BoundingSphere) +
         vertices_.capacity() * sizeof(glm::dvec3);
}

}  // namespace globe::collision
