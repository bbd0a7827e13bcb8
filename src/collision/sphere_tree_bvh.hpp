// A fair version of the sphere-tree baseline: the same per-tile sphere trees (sphere_tree.hpp),
// found through a bounding volume hierarchy over the tiles' root spheres instead of a scan of
// every root, which is what a careful engineer would build. The paper's scan grows linearly with
// the tiles; this grows with their logarithm, so QOTCD's advantage is measured against it too.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "collision/sphere_tree.hpp"

namespace globe::collision {

// A binary tree of axis-aligned boxes (ECEF) over the root spheres, built top down by splitting
// the tiles at the median of the longest axis of their centres, at most 4 tiles a leaf. Nodes
// are in depth-first order: a node's first child follows it, the second is at `second`.
class SphereTreeBvh {
 public:
  // Builds over trees (kept by reference: it must outlive this and not change).
  explicit SphereTreeBvh(const SphereTreeSet& trees);

  // As SphereTreeSet::intersect (collided iff some drawn triangle has a point within
  // radiusMeters of the centre); sphereTests counts box tests and root and node sphere tests.
  SphereTreeResult intersect(const glm::dvec3& centerEcefMeters, double radiusMeters) const;

  size_t nodeCount() const { return nodes_.size(); }
  size_t memoryBytes() const;  // the hierarchy alone (the trees are counted by their set)

 private:
  struct Node {
    glm::dvec3 low{0.0}, high{0.0};
    uint32_t second = 0;  // inner: the second child's index; leaf: 0
    uint32_t first = 0;   // leaf: the first of its tiles in order_
    uint32_t count = 0;   // leaf: how many (inner: 0)
  };
  uint32_t build(uint32_t begin, uint32_t end, const std::vector<glm::dvec3>& centres);

  const SphereTreeSet& trees_;
  std::vector<Node> nodes_;
  std::vector<uint32_t> order_;  // tile indices, leaves' ranges
};

}  // namespace globe::collision
