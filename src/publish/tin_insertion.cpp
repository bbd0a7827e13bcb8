#include "publish/tin_insertion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <unordered_set>
#include <vector>

namespace globe::publish::tin {
namespace {

// Vertices chosen on one side of the square, its samples walked in a fixed direction: both tiles
// sharing the side pass the same heights in the same order and so choose the same vertices.
void simplifySide(const std::vector<Position>& positions, const std::vector<Position>& ecef,
                  size_t first, size_t last, double maxErrorMeters, std::vector<size_t>& chosen) {
  if (last <= first + 1) return;
  // The chord's sag under the curve, L² / 8R (as sagMeters), where the side has ECEF positions.
  double sag = 0;
  if (!ecef.empty()) {
    double squared = 0;
    for (int axis = 0; axis < 3; ++axis) {
      squared += (ecef[last][axis] - ecef[first][axis]) * (ecef[last][axis] - ecef[first][axis]);
    }
    sag = squared / (8 * 6356752.314245);
  }
  double worstError = -1;
  size_t worst = first;
  for (size_t k = first + 1; k < last; ++k) {
    // The chord's point at the sample's place along the side, as a triangle interpolates it.
    const auto along = static_cast<int64_t>(k - first), span = static_cast<int64_t>(last - first);
    const double error =
        distanceMeters({span - along, along, 0}, span,
                       {positions[first], positions[last], positions[last]}, positions[k]) +
        sag;
    if (error > worstError) {
      worstError = error;
      worst = k;
    }
  }
  if (worstError <= maxErrorMeters) return;
  chosen.push_back(worst);
  simplifySide(positions, ecef, first, worst, maxErrorMeters, chosen);
  simplifySide(positions, ecef, worst, last, maxErrorMeters, chosen);
}

// Greedy insertion into a Delaunay triangulation kept in half-edge arrays (as delaunator and
// delatin keep theirs): triangle t owns half-edges 3t, 3t+1, 3t+2.
class GreedyInsertion {
 public:
  GreedyInsertion(const Grid& grid, double maxErrorMeters)
      : grid_(grid), maxErrorMeters_(maxErrorMeters) {}

  void run() {
    const int m = grid_.side - 1;
    const int sw = addVertex({0, 0}), se = addVertex({m, 0}), ne = addVertex({m, m}),
              nw = addVertex({0, m});
    fixedVertices = 4;
    const int t0 = addTriangle(sw, se, ne, -1, -1, -1);
    addTriangle(sw, ne, nw, t0 + 2, -1, -1);
    for (const GridPoint& p : sideVertices()) insertOnBorder(p);
    evaluating_ = true;
    for (size_t t = 0; t < vertexTriangles.size() / 3; ++t) evaluate(static_cast<int>(t));
    while (!queue_.empty()) {
      const Queued top = queue_.top();
      queue_.pop();
      if (top.stamp != stamps_[static_cast<size_t>(top.triangle)]) continue;
      const WorstSample candidate = candidates_[static_cast<size_t>(top.triangle)];
      // Each sample is inserted once at most, so the loop ends after side² insertions.
      for (const GridPoint& p : {candidate.at, candidate.alt}) {
        if (p.x < 0 || !inserted_.insert(grid_.sampleOf(p)).second) continue;
        split(containing(top.triangle, p), addVertex(p));
        break;
      }
    }
  }

  std::vector<GridPoint> points;
  std::vector<int> vertexTriangles;  // vertex indices into points
  int fixedVertices = 0;             // points[0, fixedVertices) lie on the border

 private:
  struct Queued {
    double errorMeters;
    int triangle;
    uint32_t stamp;
    bool operator<(const Queued& other) const {
      if (errorMeters != other.errorMeters) return errorMeters < other.errorMeters;
      return triangle > other.triangle;  // the lower index first on ties: deterministic
    }
  };

  int addVertex(GridPoint p) {
    points.push_back(p);
    positions_.push_back(grid_.positionAt(p.x, p.y));
    return static_cast<int>(points.size()) - 1;
  }

  // The sides are held to half the error: the cells beside a side bend between its vertices
  // and the interior's, which the side's own samples cannot see.
  double sideErrorMeters() const {
    return grid_.apronHeights != nullptr ? maxErrorMeters_ / 2 : maxErrorMeters_;
  }

  std::vector<GridPoint> sideVertices() const {
    const int n = grid_.side;
    std::vector<GridPoint> out;
    // South and north walked west to east, west and east south to north.
    const auto side = [&](auto pointAt) {
      std::vector<Position> positions, ecef;
      for (int k = 0; k < n; ++k) {
        const GridPoint p = pointAt(k);
        positions.push_back(grid_.positionAt(p.x, p.y));
        if (grid_.ecef != nullptr) ecef.push_back((*grid_.ecef)[grid_.sampleOf(p)]);
      }
      std::vector<size_t> chosen;
      simplifySide(positions, ecef, 0, positions.size() - 1, sideErrorMeters(), chosen);
      // A sample beside a cell (on either side) that bends more than the error is kept: without
      // it no TIN can follow that cell. Both tiles see the same four cells (the apron).
      if (grid_.apronHeights != nullptr) {
        for (int k = 1; k + 1 < n; ++k) {
          // The four cells around the sample, two inside the tile and two beyond.
          const GridPoint p = pointAt(k);
          double twist = 0;
          for (int dx = -1; dx <= 0; ++dx) {
            for (int dy = -1; dy <= 0; ++dy) {
              twist = std::max(twist, grid_.cellTwistMeters(p.x + dx, p.y + dy));
            }
          }
          if (twist > sideErrorMeters()) chosen.push_back(static_cast<size_t>(k));
        }
      }
      std::sort(chosen.begin(), chosen.end());
      chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
      for (size_t k : chosen) out.push_back(pointAt(static_cast<int>(k)));
    };
    side([](int k) { return GridPoint{k, 0}; });
    side([&](int k) { return GridPoint{k, n - 1}; });
    side([](int k) { return GridPoint{0, k}; });
    side([&](int k) { return GridPoint{n - 1, k}; });
    return out;
  }

  void link(int a, int b) {
    halfedges_[static_cast<size_t>(a)] = b;
    if (b >= 0) halfedges_[static_cast<size_t>(b)] = a;
  }

  // Writes triangle (a, b, c) at half-edge index e (a new one when -1), linking its edges ab,
  // bc, ca to their twins; returns its first half-edge.
  int addTriangle(int a, int b, int c, int ab, int bc, int ca, int e = -1) {
    if (e < 0) {
      e = static_cast<int>(vertexTriangles.size());
      vertexTriangles.insert(vertexTriangles.end(), {a, b, c});
      halfedges_.insert(halfedges_.end(), {-1, -1, -1});
      stamps_.push_back(0);
      candidates_.push_back({});
    } else {
      vertexTriangles[static_cast<size_t>(e)] = a;
      vertexTriangles[static_cast<size_t>(e) + 1] = b;
      vertexTriangles[static_cast<size_t>(e) + 2] = c;
    }
    link(e, ab);
    link(e + 1, bc);
    link(e + 2, ca);
    if (evaluating_) evaluate(e / 3);
    return e;
  }

  void evaluate(int t) {
    const auto i = static_cast<size_t>(t) * 3;
    const std::array<int, 3> v{vertexTriangles[i], vertexTriangles[i + 1], vertexTriangles[i + 2]};
    const WorstSample worst =
        worstSampleIn(grid_,
                      {points[static_cast<size_t>(v[0])], points[static_cast<size_t>(v[1])],
                       points[static_cast<size_t>(v[2])]},
                      {positions_[static_cast<size_t>(v[0])], positions_[static_cast<size_t>(v[1])],
                       positions_[static_cast<size_t>(v[2])]},
                      true);
    const uint32_t stamp = ++stamps_[static_cast<size_t>(t)];
    candidates_[static_cast<size_t>(t)] = worst;
    if (worst.errorMeters > maxErrorMeters_ && worst.at.x >= 0) {
      queue_.push({worst.errorMeters, t, stamp});
    }
  }

  GridPoint at(int halfedge) const {
    return points[static_cast<size_t>(vertexTriangles[static_cast<size_t>(halfedge)])];
  }
  static int next(int e) { return e - e % 3 + (e + 1) % 3; }
  static int prev(int e) { return e - e % 3 + (e + 2) % 3; }

  void insertOnBorder(GridPoint p) {
    const int v = addVertex(p);
    fixedVertices = v + 1;
    for (int e = 0; e < static_cast<int>(halfedges_.size()); ++e) {
      if (halfedges_[static_cast<size_t>(e)] >= 0) continue;
      const GridPoint s = at(e), f = at(next(e));
      if (orient(s, f, p) != 0) continue;
      if (std::min(s.x, f.x) <= p.x && p.x <= std::max(s.x, f.x) && std::min(s.y, f.y) <= p.y &&
          p.y <= std::max(s.y, f.y)) {
        splitEdge(e, v);
        return;
      }
    }
  }

  // The triangle holding p: t, usually; else found among all (a crossing's sample may lie beyond
  // the triangles beside it).
  int containing(int t, GridPoint p) const {
    const auto holds = [&](int triangle) {
      const auto e = static_cast<size_t>(triangle) * 3;
      const GridPoint a = points[static_cast<size_t>(vertexTriangles[e])],
                      b = points[static_cast<size_t>(vertexTriangles[e + 1])],
                      c = points[static_cast<size_t>(vertexTriangles[e + 2])];
      return orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0;
    };
    if (holds(t)) return t;
    for (int other = 0; other < static_cast<int>(vertexTriangles.size() / 3); ++other) {
      if (holds(other)) return other;
    }
    return t;
  }

  // Inserts vertex v inside triangle t (on one of its edges when collinear with it).
  void split(int t, int v) {
    const int e0 = t * 3;
    const GridPoint p = points[static_cast<size_t>(v)];
    for (int k = 0; k < 3; ++k) {
      if (orient(at(e0 + k), at(e0 + (k + 1) % 3), p) == 0) {
        splitEdge(e0 + k, v);
        return;
      }
    }
    const int p0 = vertexTriangles[static_cast<size_t>(e0)],
              p1 = vertexTriangles[static_cast<size_t>(e0) + 1],
              p2 = vertexTriangles[static_cast<size_t>(e0) + 2];
    const int h0 = halfedges_[static_cast<size_t>(e0)],
              h1 = halfedges_[static_cast<size_t>(e0) + 1],
              h2 = halfedges_[static_cast<size_t>(e0) + 2];
    const int a = addTriangle(p0, p1, v, h0, -1, -1, e0);
    const int b = addTriangle(p1, p2, v, h1, -1, a + 1);
    const int c = addTriangle(p2, p0, v, h2, a + 2, b + 1);
    legalize(a);
    legalize(b);
    legalize(c);
  }

  // Inserts vertex v on half-edge e (from s to f, o opposite), splitting the triangles on both
  // sides of it.
  void splitEdge(int e, int v) {
    const int twin = halfedges_[static_cast<size_t>(e)];
    const int e0 = e - e % 3;
    const int s = vertexTriangles[static_cast<size_t>(e)],
              f = vertexTriangles[static_cast<size_t>(next(e))],
              o = vertexTriangles[static_cast<size_t>(prev(e))];
    const int hn = halfedges_[static_cast<size_t>(next(e))],
              hp = halfedges_[static_cast<size_t>(prev(e))];
    if (twin < 0) {
      const int a = addTriangle(o, s, v, hp, -1, -1, e0);
      const int b = addTriangle(v, f, o, -1, hn, a + 2);
      legalize(a);
      legalize(b + 1);
      return;
    }
    const int t0 = twin - twin % 3;
    const int q = vertexTriangles[static_cast<size_t>(prev(twin))];
    const int hbn = halfedges_[static_cast<size_t>(next(twin))],
              hbp = halfedges_[static_cast<size_t>(prev(twin))];
    const int a = addTriangle(o, s, v, hp, -1, -1, e0);
    const int b = addTriangle(v, f, o, -1, hn, a + 2, t0);
    const int c = addTriangle(q, f, v, hbp, b, -1);
    const int d = addTriangle(s, q, v, hbn, c + 2, a + 1);
    legalize(a);
    legalize(b + 1);
    legalize(c);
    legalize(d);
  }

  // Flips half-edge e (opposite the newly inserted vertex) while the vertex across it lies
  // inside the circle of e's triangle.
  void legalize(int e) {
    const int twin = halfedges_[static_cast<size_t>(e)];
    if (twin < 0) return;
    const int a0 = e - e % 3, b0 = twin - twin % 3;
    const int al = next(e), ar = prev(e), bl = prev(twin), br = next(twin);
    const int p0 = vertexTriangles[static_cast<size_t>(ar)],
              pr = vertexTriangles[static_cast<size_t>(e)],
              pl = vertexTriangles[static_cast<size_t>(al)],
              p1 = vertexTriangles[static_cast<size_t>(bl)];
    const int64_t inside =
        inCircle(points[static_cast<size_t>(pr)], points[static_cast<size_t>(pl)],
                 points[static_cast<size_t>(p0)], points[static_cast<size_t>(p1)]);
    // On the circle (a grid cell, most often) either diagonal is Delaunay: the one running
    // north-west to south-east, as globe splits its cells, so that the TIN bends where the
    // drawn surface does. Never back, so no flip repeats.
    const auto northWestToSouthEast = [&](int a, int b) {
      const GridPoint pa = points[static_cast<size_t>(a)], pb = points[static_cast<size_t>(b)];
      return int64_t{pb.x - pa.x} * (pb.y - pa.y) < 0;
    };
    if (inside < 0 ||
        (inside == 0 && (northWestToSouthEast(pr, pl) || !northWestToSouthEast(p0, p1)))) {
      return;
    }
    const int hal = halfedges_[static_cast<size_t>(al)], har = halfedges_[static_cast<size_t>(ar)],
              hbl = halfedges_[static_cast<size_t>(bl)], hbr = halfedges_[static_cast<size_t>(br)];
    const int a = addTriangle(p0, p1, pl, -1, hbl, hal, a0);
    const int b = addTriangle(p1, p0, pr, a, har, hbr, b0);
    legalize(a + 1);
    legalize(b + 2);
  }

  const Grid& grid_;
  double maxErrorMeters_;
  bool evaluating_ = false;
  std::vector<Position> positions_;
  std::vector<int> halfedges_;
  std::vector<uint32_t> stamps_;
  std::vector<WorstSample> candidates_;
  std::priority_queue<Queued> queue_;
  std::unordered_set<uint32_t> inserted_;
};

}  // namespace

Insertion greedyInsertion(const Grid& grid, double maxErrorMeters) {
  GreedyInsertion insertion(grid, maxErrorMeters);
  insertion.run();
  return {insertion.points, insertion.vertexTriangles, insertion.fixedVertices};
}

}  // namespace globe::publish::tin
