// Top-down median-split BVH over the tiles' root spheres; stack traversal with an early exit.
#include "collision/sphere_tree_bvh.hpp"

#include <algorithm>
#include <array>
#include <numeric>

#include <glm/common.hpp>

namespace globe::collision {
namespace {

constexpr uint32_t kLeafTiles = 4;

// Squared distance from p to the box [low, high] (0 inside).
double squaredDistanceToBox(const glm::dvec3& p, const glm::dvec3& low, const glm::dvec3& high) {
  const glm::dvec3 outside = glm::max(glm::max(low - p, p - high), glm::dvec3(0.0));
  return outside.x * outside.x + outside.y * outside.y + outside.z * outside.z;
}

}  // namespace

SphereTreeBvh::SphereTreeBvh(const SphereTreeSet& trees) : trees_(trees) {
  const auto count = static_cast<uint32_t>(trees.tileCount());
  order_.resize(count);
  std::iota(order_.begin(), order_.end(), 0u);
  std::vector<glm::dvec3> centres(count);
  for (uint32_t t = 0; t < count; ++t) centres[t] = trees.node(t, 0, 0).centerEcefMeters;
  nodes_.reserve(count == 0 ? 0 : 2 * (count / kLeafTiles + 1));
  if (count > 0) build(0, count, centres);
}

uint32_t SphereTreeBvh::build(uint32_t begin, uint32_t end,
                              const std::vector<glm::dvec3>& centres) {
  const auto index = static_cast<uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Node node;
  node.low = glm::dvec3(HUGE_VAL);
  node.high = glm::dvec3(-HUGE_VAL);
  glm::dvec3 centreLow(HUGE_VAL), centreHigh(-HUGE_VAL);
  for (uint32_t k = begin; k < end; ++k) {
    const BoundingSphere root = trees_.node(order_[k], 0, 0);
    node.low = glm::min(node.low, root.centerEcefMeters - root.radiusMeters);
    node.high = glm::max(node.high, root.centerEcefMeters + root.radiusMeters);
    centreLow = glm::min(centreLow, centres[order_[k]]);
    centreHigh = glm::max(centreHigh, centres[order_[k]]);
  }
  if (end - begin <= kLeafTiles) {
    node.first = begin;
    node.count = end - begin;
    nodes_[index] = node;
    return index;
  }
  const glm::dvec3 extent = centreHigh - centreLow;
  const int axis =
      extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&](uint32_t a, uint32_t b) { return centres[a][axis] < centres[b][axis]; });
  build(begin, middle, centres);
  node.second = build(middle, end, centres);
  nodes_[index] = node;
  return index;
}

SphereTreeResult SphereTreeBvh::intersect(const glm::dvec3& center, double radius) const {
  SphereTreeResult result;
  if (nodes_.empty()) return result;
  const double radiusSquared = radius * radius;
  std::array<uint32_t, 64> stack{};
  size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    ++result.sphereTests;
    if (!(squaredDistanceToBox(center, node.low, node.high) <= radiusSquared)) continue;
    if (node.count > 0) {
      for (uint32_t k = node.first; k < node.first + node.count; ++k) {
        const SphereTreeResult tile = trees_.intersectTile(order_[k], center, radius);
        result.sphereTests += tile.sphereTests;
        result.triangleTests += tile.triangleTests;
        if (tile.collided) {
          result.collided = true;
          result.hit = tile.hit;
          return result;
        }
      }
      continue;
    }
    // Depth-first; a tree of n tiles is ~log2(n / 4) deep, far within the stack.
    if (top + 2 > stack.size()) break;
    stack[top++] = node.second;
    stack[top++] = static_cast<uint32_t>(&node - nodes_.data()) + 1;
  }
  return result;
}

size_t SphereTreeBvh::memoryBytes() const {
  return nodes_.capacity() * sizeof(Node) + order_.capacity() * sizeof(uint32_t);
}

}  // namespace globe::collision
