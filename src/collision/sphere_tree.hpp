// The sphere-tree baseline the paper compares QOTCD with (its section 4, after reference [21]):
// per tile a quadtree of bounding spheres down to the drawn triangles, against a camera sphere.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "collision/terrain_array.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::collision {

// The paper's camera sphere: "the radius of the sphere covering the camera is 50 meters".
inline constexpr double kCameraSphereRadiusMeters = 50.0;

struct BoundingSphere {
  glm::dvec3 centerEcefMeters{0.0};
  double radiusMeters = 0.0;
};

// One drawn triangle: the south-west or north-east half of quad (quadRow, quadColumn) of the
// tile at position `tile` of the set (= of the array's tiles()), by the diagonal rule of
// terrain/tile_mesh.hpp.
struct TriangleRef {
  uint32_t tile = 0;
  uint32_t quadRow = 0;
  uint32_t quadColumn = 0;
  bool southWest = false;
  auto operator<=>(const TriangleRef&) const = default;
};

// One query and its cost in the paper's terms, T = Nv x Cv + Np x Cp.
struct SphereTreeResult {
  bool collided = false;
  uint32_t sphereTests = 0;    // Nv: camera sphere against a node sphere (roots included)
  uint32_t triangleTests = 0;  // Np: camera sphere against a triangle
  TriangleRef hit{};           // the first triangle found within the radius, when collided
};

// Squared distance from p to the closed triangle (a, b, c); degenerate triangles (collapsed
// pole quads) are handled as segments or points. After Ericson, Real-Time Collision Detection,
// 5.1.5.
double squaredDistanceToTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                 const glm::dvec3& c);

// The sphere trees of every tile of a rendering tile array, built at preprocessing.
// - Geometry: each tile's N x N grid vertices in double ECEF exactly as the mesh places them
//   (terrain::tileVertexEcefMeters of the surface height, no-data = 0 m); skirts are left out.
// - Tree: a complete quadtree over the tile's (N-1)^2 quads: node level 0 is the whole tile,
//   level l cuts it into 2^l x 2^l sub-blocks, the last level (log2(N-1)) is one quad (its two
//   triangles). Each node's sphere (centre: the middle of its vertices' bounding box) holds every
//   vertex of its sub-block, hence every triangle in it. Nodes are packed level by level with
//   the children of node k at 4k..4k+3 of the next level (Morton order): no child pointers.
// - Query: the camera sphere against every tile's root sphere (a struct-of-arrays scan),
//   descending where the spheres overlap (closed test), then the quad's two triangles by exact
//   closest-point distance; it stops at the first triangle within the radius.
// Semantics: collided iff some drawn triangle has a point within radiusMeters of the centre.
// A camera more than radiusMeters below the surface is therefore NOT a collision.
class SphereTreeSet {
 public:
  // Replaces the contents with one tree per tile of array.tiles(), in that order. The array's
  // blocks are read only here.
  void build(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid);

  SphereTreeResult intersect(const glm::dvec3& centerEcefMeters, double radiusMeters) const;
  // The same for one tile (its root sphere test included).
  SphereTreeResult intersectTile(uint32_t tile, const glm::dvec3& centerEcefMeters,
                                 double radiusMeters) const;
  // Every triangle within radiusMeters, in tile then tree order, with no early exit.
  std::vector<TriangleRef> trianglesWithin(const glm::dvec3& centerEcefMeters,
                                           double radiusMeters) const;

  size_t tileCount() const { return tiles_.size(); }
  uint32_t verticesPerSide(uint32_t tile) const { return tiles_[tile].verticesPerSide; }
  // Node levels below the root: log2(N-1).
  uint32_t depth(uint32_t tile) const { return tiles_[tile].depth; }
  glm::dvec3 vertex(uint32_t tile, uint32_t row, uint32_t column) const;
  // Node `index` (0 .. 4^level - 1) of a level; its sub-block by nodeBlock.
  BoundingSphere node(uint32_t tile, uint32_t level, uint32_t index) const;
  struct Block {
    uint32_t firstRow = 0;
    uint32_t firstColumn = 0;
    uint32_t quadsPerSide = 0;
  };
  Block nodeBlock(uint32_t tile, uint32_t level, uint32_t index) const;
  // Heap bytes held (nodes, vertices, root arrays, per-tile records).
  size_t memoryBytes() const;

 private:
  struct TileTree {
    uint64_t firstNode = 0;
    uint64_t firstVertex = 0;
    uint32_t verticesPerSide = 0;
    uint32_t depth = 0;
  };
  // Root spheres as struct-of-arrays for the scan over all tiles.
  std::vector<double> rootX_, rootY_, rootZ_, rootRadius_;
  std::vector<TileTree> tiles_;
  std::vector<BoundingSphere> nodes_;  // per tile: levels 0..depth, 4^l nodes each
  std::vector<glm::dvec3> vertices_;   // per tile: N x N, row-major

  template <bool kFirstHitOnly>
  bool descend(uint32_t tile, uint32_t level, uint32_t index, const glm::dvec3& center,
               double radius, SphereTreeResult& result, std::vector<TriangleRef>* found) const;
};

}  // namespace globe::collision
