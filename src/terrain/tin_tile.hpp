// A terrain tile given as a TIN (quantized-mesh's triangles, as the producer simplified them)
// for QOTCD as the paper reads one: the Intersecting Point's triangle found in O(1) through a
// grid of triangle lists over the tile (built once, where the tile loads), H the highest of that
// triangle's vertices (conservative: never below the surface drawn), the exact height its plane.
// As the grid rule does on rows and columns, a point on an edge takes the higher of the edge's
// two vertices and a point on a vertex that vertex.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "geo/globe_rectangle.hpp"

namespace globe::terrain {

// A vertex across its tile: u from the west edge (0) to the east (1), v from the south (0) to
// the north (1), as quantized-mesh writes them (its 0..32767 divided by 32767).
struct TinVertex {
  double u = 0, v = 0;
  double heightMeters = 0;
};

// Twice the signed area of triangle abc in (u, v): positive counter-clockwise seen from above
// (u east, v north), 0 for a degenerate one.
inline double twiceSignedArea(const TinVertex& a, const TinVertex& b, const TinVertex& c) {
  return (b.u - a.u) * (c.v - a.v) - (c.u - a.u) * (b.v - a.v);
}

struct TinHeight {
  bool found = false;               // false: no triangle covers the point (outside the tile)
  double conservativeMeters = 0.0;  // the paper's H: the triangle's highest vertex
  double exactMeters = 0.0;         // the triangle's plane at the point
  uint32_t triangle = 0;            // its index
};

class TinTile {
 public:
  // `triangles`: three vertex indices each. Errors name `name`: an index past the vertices, no
  // triangles, a vertex off the tile.
  static Result<TinTile> build(const geo::GlobeRectangle& rectangle,
                               std::vector<TinVertex> vertices, std::vector<uint32_t> triangles,
                               const std::string& name);

  // H and the exact height at a point inside the tile's rectangle (radians).
  TinHeight heightAt(double longitudeRadians, double latitudeRadians) const;

  const geo::GlobeRectangle& rectangle() const { return rectangle_; }
  size_t triangleCount() const { return triangles_.size() / 3; }
  uint32_t cellsPerSide() const { return cells_; }
  const std::vector<TinVertex>& vertices() const { return vertices_; }
  const std::vector<uint32_t>& triangles() const { return triangles_; }
  double maximumHeightMeters() const { return maximumHeightMeters_; }
  double minimumHeightMeters() const { return minimumHeightMeters_; }
  // Unit ECEF normals the producer gave per vertex (quantized-mesh's oct-encoded normals), or
  // empty: the mesh then derives them from its triangles.
  const std::vector<glm::vec3>& normals() const { return normals_; }
  // Sets them: false (and none kept) unless there is one per vertex.
  bool setNormals(std::vector<glm::vec3> normals);
  // Where the mesh draws vertex k (before its level's rounding, tile_mesh.hpp) and collision
  // takes it: (west + u·width, south + v·height) at its height, the edges' u and v of 0 and 1
  // exactly on the tile's bounds.
  glm::dvec3 vertexEcefMeters(const geo::Ellipsoid& ellipsoid, uint32_t k) const;
  // Triangle t's three vertices so, less `origin` (the differences keep their precision).
  std::array<glm::dvec3, 3> triangleEcefMeters(const geo::Ellipsoid& ellipsoid, uint32_t t,
                                               const glm::dvec3& origin = glm::dvec3(0.0)) const;
  // Each triangle meeting the box [u0, u1] x [v0, v1] (tile fractions) once, perhaps with
  // others near it, from the cell grid.
  void forEachTriangleNear(double u0, double v0, double u1, double v1,
                           const std::function<void(uint32_t)>& visit) const;

 private:
  TinTile() = default;
  void prepareTriangles();
  void buildCells();
  // H and the plane at (u, v) if triangle t holds the point.
  bool tryTriangle(uint32_t t, double u, double v, TinHeight& out) const;

  // A triangle's barycentric weights as affine functions of (u, v) (wa = a0 + au·u + av·v, wb
  // likewise, wc = 1 − wa − wb) and its vertices' heights: a query multiplies, never divides.
  struct Prepared {
    double a0, au, av, b0, bu, bv;
    double ha, hb, hc;
  };

  geo::GlobeRectangle rectangle_{};
  double uPerRadian_ = 1, vPerRadian_ = 1;
  std::vector<TinVertex> vertices_;
  std::vector<uint32_t> triangles_;
  std::vector<glm::vec3> normals_;
  double maximumHeightMeters_ = 0, minimumHeightMeters_ = 0;
  std::vector<Prepared> prepared_;
  uint32_t cells_ = 1;
  // The triangles meeting each cell (row-major from the south-west), as offsets into one list.
  std::vector<uint32_t> cellStart_, cellTriangles_;
};

}  // namespace globe::terrain
