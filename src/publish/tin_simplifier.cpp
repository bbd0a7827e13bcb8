#include "publish/tin_simplifier.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <queue>
#include <unordered_set>
#include <vector>

namespace globe::publish {
namespace {

// Grid coordinates: x the column (east), y rows from the south (north up), so that
// counter-clockwise is positive as in the output.
struct GridPoint {
  int x, y;
};

int64_t orient(GridPoint a, GridPoint b, GridPoint c) {
  return int64_t{b.x - a.x} * (c.y - a.y) - int64_t{b.y - a.y} * (c.x - a.x);
}

// Positive where d lies inside the circle through the counter-clockwise a, b, c, zero on it.
// Exact: the coordinates are small integers.
int64_t inCircle(GridPoint a, GridPoint b, GridPoint c, GridPoint d) {
  const int64_t adx = a.x - d.x, ady = a.y - d.y;
  const int64_t bdx = b.x - d.x, bdy = b.y - d.y;
  const int64_t cdx = c.x - d.x, cdy = c.y - d.y;
  const int64_t al = adx * adx + ady * ady;
  const int64_t bl = bdx * bdx + bdy * bdy;
  const int64_t cl = cdx * cdx + cdy * cdy;
  return adx * (bdy * cl - bl * cdy) - ady * (bdx * cl - bl * cdx) + al * (bdx * cdy - bdy * cdx);
}

using Position = std::array<double, 3>;

// The distance between a sample's position and the triangle's point at the sample's grid place
// (the weights over the corners' positions, wSum their total).
double distanceMeters(const std::array<int64_t, 3>& w, int64_t wSum,
                      const std::array<Position, 3>& corners, const Position& sample) {
  double squared = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double interpolated = (static_cast<double>(w[0]) * corners[0][axis] +
                                 static_cast<double>(w[1]) * corners[1][axis] +
                                 static_cast<double>(w[2]) * corners[2][axis]) /
                                static_cast<double>(wSum);
    const double d = interpolated - sample[axis];
    squared += d * d;
  }
  return std::sqrt(squared);
}

// The samples' positions and the grid's shape every pass works on.
struct Grid {
  const std::vector<Position>& positions;
  int side;
  // Whether the surface between samples counts: the grid's own triangles, each cell split from
  // north-west to south-east as globe draws it.
  bool betweenSamples = false;
  // The samples in ECEF, where a flat triangle's sag under the curved globe counts; null for a
  // plain height field.
  const std::vector<Position>* ecef = nullptr;
  // The heights with a ring of the neighbours' samples ((side + 2)², rows from the north), so
  // that a side's vertices can depend on the cells on both sides of it; null without.
  const std::vector<double>* apronHeights = nullptr;

  double apronHeightAt(int x, int y) const {  // x, y in [-1, side]
    return (*apronHeights)[static_cast<size_t>(side - y) * (side + 2) + static_cast<size_t>(x + 1)];
  }
  // How far the cell with south-west corner (x, y) bends: its two diagonals' midpoints apart.
  // A TIN edge along the other diagonal misses the drawn surface by this at the cell's centre.
  double cellTwistMeters(int x, int y) const {
    return std::fabs(apronHeightAt(x, y + 1) + apronHeightAt(x + 1, y) - apronHeightAt(x, y) -
                     apronHeightAt(x + 1, y + 1)) /
           2;
  }

  const Position& positionAt(int x, int y) const {
    return positions[static_cast<size_t>(side - 1 - y) * side + x];
  }
  bool onBorder(int x, int y) const { return x == 0 || y == 0 || x == side - 1 || y == side - 1; }
  uint32_t sampleOf(GridPoint p) const {
    return static_cast<uint32_t>((side - 1 - p.y) * side + p.x);
  }
};

// How far a flat triangle through these samples lies below the globe's curve at most: the cap
// under its circumscribed circle, r² / 2R on the polar radius (the smaller: more sag). A
// triangle flat in ECEF (two corners at a pole) sags as its longest side's chord, L² / 8R.
double sagMeters(const Grid& grid, const std::array<GridPoint, 3>& v) {
  if (grid.ecef == nullptr) return 0;
  constexpr double kPolarRadiusMeters = 6356752.314245;
  std::array<Position, 3> p;
  for (size_t k = 0; k < 3; ++k) p[k] = (*grid.ecef)[grid.sampleOf(v[k])];
  const auto sub = [](const Position& a, const Position& b) {
    return Position{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  const auto norm = [](const Position& a) {
    return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  };
  const Position ab = sub(p[1], p[0]), ac = sub(p[2], p[0]), bc = sub(p[2], p[1]);
  const Position cross{ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
                       ab[0] * ac[1] - ab[1] * ac[0]};
  const double lab = norm(ab), lac = norm(ac), lbc = norm(bc);
  const double twiceArea = norm(cross);
  const double longest = std::max({lab, lac, lbc});
  if (twiceArea <= 1e-9 * longest * longest) return longest * longest / (8 * kPolarRadiusMeters);
  const double radius = std::min(lab * lac * lbc / (2 * twiceArea), longest);
  return radius * radius / (2 * kPolarRadiusMeters);
}

struct WorstSample {
  double errorMeters = -1;
  GridPoint at{-1, -1};   // the sample to insert for it; (-1, -1) when there is none
  GridPoint alt{-1, -1};  // another, should `at` be a vertex already
};

struct Crossing {
  double errorMeters = -1;
  double x = 0, y = 0;
  GridPoint from{-1, -1}, to{-1, -1};  // the grid line's samples either side of it
};

// Where the triangle's edges cross the grid's lines (columns, rows and the cells' north-west to
// south-east diagonals), the distance between the edge (flat between its corners) and the
// grid's surface there (flat between the line's two samples): with the samples, the only places
// two piecewise-flat surfaces can be farthest apart.
Crossing worstEdgeCrossing(const Grid& grid, const std::array<GridPoint, 3>& v,
                           const std::array<Position, 3>& corners) {
  Crossing worst;
  const auto lerp = [](const Position& a, const Position& b, double t) {
    return Position{a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
  };
  const auto consider = [&](const Position& onEdge, const Position& onGrid, double x, double y,
                            GridPoint from, GridPoint to) {
    double squared = 0;
    for (int axis = 0; axis < 3; ++axis)
      squared += (onEdge[axis] - onGrid[axis]) * (onEdge[axis] - onGrid[axis]);
    const double error = std::sqrt(squared);
    if (error > worst.errorMeters) worst = {error, x, y, from, to};
  };
  for (int k = 0; k < 3; ++k) {
    const GridPoint a = v[static_cast<size_t>(k)], b = v[static_cast<size_t>((k + 1) % 3)];
    const Position& pa = corners[static_cast<size_t>(k)];
    const Position& pb = corners[static_cast<size_t>((k + 1) % 3)];
    const int dx = b.x - a.x, dy = b.y - a.y;
    // Columns x = c: the crossing lies between rows y0 and y0 + 1 (skipped on a sample).
    for (int c = std::min(a.x, b.x) + 1; c < std::max(a.x, b.x); ++c) {
      const int numerator = (c - a.x) * dy;
      if (numerator % dx == 0) continue;
      const double t = static_cast<double>(c - a.x) / dx, y = a.y + t * dy;
      const int y0 = static_cast<int>(std::floor(y));
      consider(lerp(pa, pb, t), lerp(grid.positionAt(c, y0), grid.positionAt(c, y0 + 1), y - y0), c,
               y, {c, y0}, {c, y0 + 1});
    }
    // Rows y = c.
    for (int c = std::min(a.y, b.y) + 1; c < std::max(a.y, b.y); ++c) {
      const int numerator = (c - a.y) * dx;
      if (numerator % dy == 0) continue;
      const double t = static_cast<double>(c - a.y) / dy, x = a.x + t * dx;
      const int x0 = static_cast<int>(std::floor(x));
      consider(lerp(pa, pb, t), lerp(grid.positionAt(x0, c), grid.positionAt(x0 + 1, c), x - x0), x,
               c, {x0, c}, {x0 + 1, c});
    }
    // Diagonals x + y = c, from (x0, c − x0) (north-west) to (x0 + 1, c − x0 − 1).
    const int sa = a.x + a.y, sb = b.x + b.y, ds = sb - sa;
    for (int c = std::min(sa, sb) + 1; c < std::max(sa, sb); ++c) {
      const int numerator = (c - sa) * dx;
      if (numerator % ds == 0) continue;
      const double t = static_cast<double>(c - sa) / ds, x = a.x + t * dx;
      const int x0 = static_cast<int>(std::floor(x));
      consider(lerp(pa, pb, t),
               lerp(grid.positionAt(x0, c - x0), grid.positionAt(x0 + 1, c - x0 - 1), x - x0), x,
               c - x, {x0, c - x0}, {x0 + 1, c - x0 - 1});
    }
  }
  return worst;
}

// The triangle's largest error and the sample to insert for it: the sample farthest from the
// triangle, or, where an edge crossing is farther (Grid::betweenSamples), the insertable sample
// nearest that crossing. Border samples are skipped where asked (the sides' own simplification
// bounds them). The first in scan order on ties, so that the result depends on the data alone.
WorstSample worstSampleIn(const Grid& grid, const std::array<GridPoint, 3>& v,
                          const std::array<Position, 3>& corners, bool skipBorder) {
  const int64_t area = orient(v[0], v[1], v[2]);
  WorstSample worst;
  if (area <= 0) return worst;
  const double sag = sagMeters(grid, v);
  Crossing crossing = grid.betweenSamples ? worstEdgeCrossing(grid, v, corners) : Crossing{};
  if (crossing.errorMeters >= 0) crossing.errorMeters += sag;
  double nearestSquared = INFINITY;
  GridPoint nearest{-1, -1};
  const int x0 = std::min({v[0].x, v[1].x, v[2].x}), x1 = std::max({v[0].x, v[1].x, v[2].x});
  const int y0 = std::min({v[0].y, v[1].y, v[2].y}), y1 = std::max({v[0].y, v[1].y, v[2].y});
  // Each weight is an edge function, linear in x: per row, the span where all three are >= 0
  // is found exactly in integers, and the weights stepped along it.
  const std::array<int64_t, 3> stepX{-(v[2].y - v[1].y), -(v[0].y - v[2].y), -(v[1].y - v[0].y)};
  for (int y = y0; y <= y1; ++y) {
    const GridPoint start{x0, y};
    std::array<int64_t, 3> w{orient(v[1], v[2], start), orient(v[2], v[0], start),
                             orient(v[0], v[1], start)};
    int64_t first = x0, last = x1;
    for (int k = 0; k < 3; ++k) {
      if (stepX[k] == 0) {
        if (w[k] < 0) first = last + 1;
      } else if (stepX[k] > 0) {
        if (w[k] < 0) first = std::max(first, x0 + (-w[k] + stepX[k] - 1) / stepX[k]);
      } else {
        if (w[k] < 0)
          first = last + 1;
        else
          last = std::min(last, x0 + w[k] / -stepX[k]);
      }
    }
    for (int k = 0; k < 3; ++k) w[k] += stepX[k] * (first - x0);
    for (int64_t x = first; x <= last; ++x, w[0] += stepX[0], w[1] += stepX[1], w[2] += stepX[2]) {
      if (skipBorder && grid.onBorder(static_cast<int>(x), y)) continue;
      // A corner is exact; rounding in the weights must not make it a candidate again.
      if (w[0] == area || w[1] == area || w[2] == area) continue;
      const double error =
          distanceMeters(w, area, corners, grid.positionAt(static_cast<int>(x), y)) + sag;
      if (error > worst.errorMeters) worst = {error, {static_cast<int>(x), y}};
      if (crossing.errorMeters > 0) {
        const double d =
            (static_cast<double>(x) - crossing.x) * (static_cast<double>(x) - crossing.x) +
            (y - crossing.y) * (y - crossing.y);
        if (d < nearestSquared) {
          nearestSquared = d;
          nearest = {static_cast<int>(x), y};
        }
      }
    }
  }
  if (crossing.errorMeters > worst.errorMeters) {
    worst = {crossing.errorMeters, nearest, {-1, -1}};
    if (nearest.x < 0) {
      // No sample of this triangle: the grid line's own samples, wherever they lie, the nearer
      // first (never a side's: those are the sides' to choose).
      GridPoint first = crossing.from, second = crossing.to;
      const double toFrom = std::hypot(first.x - crossing.x, first.y - crossing.y);
      const double toTo = std::hypot(second.x - crossing.x, second.y - crossing.y);
      if (toTo < toFrom) std::swap(first, second);
      const GridPoint none{-1, -1};
      worst.at = skipBorder && grid.onBorder(first.x, first.y) ? none : first;
      worst.alt = skipBorder && grid.onBorder(second.x, second.y) ? none : second;
      if (worst.at.x < 0) std::swap(worst.at, worst.alt);
    }
  }
  return worst;
}

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

// Half-edge collapses of the inserted vertices (never the border's) onto a neighbour, each kept
// only where every new triangle stays counter-clockwise and every sample it covers within the
// error; repeated while a pass removes any.
class Decimation {
 public:
  Decimation(const Grid& grid, double maxErrorMeters, std::vector<GridPoint> points,
             const std::vector<int>& triangles, int fixedVertices)
      : grid_(grid),
        maxErrorMeters_(maxErrorMeters),
        points_(std::move(points)),
        fixedVertices_(fixedVertices),
        incident_(points_.size()) {
    for (size_t i = 0; i < triangles.size(); i += 3) {
      addTriangle({triangles[i], triangles[i + 1], triangles[i + 2]});
    }
  }

  void run() {
    // A vertex is tried again only when a collapse changed its star since its last try.
    dirty_.assign(points_.size(), true);
    for (int pass = 0; pass < 8; ++pass) {
      bool removedAny = false;
      for (int v = static_cast<int>(points_.size()) - 1; v >= fixedVertices_; --v) {
        if (!dirty_[static_cast<size_t>(v)]) continue;
        dirty_[static_cast<size_t>(v)] = false;
        removedAny = tryRemove(v) || removedAny;
      }
      if (!removedAny) break;
    }
  }

  GridTin result() const {
    GridTin tin;
    std::vector<int> index(points_.size(), -1);
    for (size_t t = 0; t < vertexTriangles.size(); ++t) {
      if (!alive_[t]) continue;
      for (int v : vertexTriangles[t]) {
        auto& i = index[static_cast<size_t>(v)];
        if (i < 0) {
          i = static_cast<int>(tin.samples.size());
          tin.samples.push_back(grid_.sampleOf(points_[static_cast<size_t>(v)]));
        }
        tin.triangles.push_back(static_cast<uint32_t>(i));
      }
    }
    return tin;
  }

 private:
  using Triangle = std::array<int, 3>;

  void addTriangle(const Triangle& t) {
    const int index = static_cast<int>(vertexTriangles.size());
    vertexTriangles.push_back(t);
    alive_.push_back(true);
    for (int v : t) incident_[static_cast<size_t>(v)].push_back(index);
  }

  const Position& positionOf(int v) const {
    const GridPoint p = points_[static_cast<size_t>(v)];
    return grid_.positionAt(p.x, p.y);
  }

  bool tryRemove(int v) {
    std::vector<int> star;
    for (int t : incident_[static_cast<size_t>(v)]) {
      if (alive_[static_cast<size_t>(t)]) star.push_back(t);
    }
    std::vector<int> neighbours;
    for (int t : star) {
      for (int w : vertexTriangles[static_cast<size_t>(t)]) {
        if (w != v && std::find(neighbours.begin(), neighbours.end(), w) == neighbours.end()) {
          neighbours.push_back(w);
        }
      }
    }
    double bestError = INFINITY;
    int best = -1;
    for (int u : neighbours) {
      const double error = collapseError(star, v, u, bestError);
      if (error < bestError) {
        bestError = error;
        best = u;
      }
    }
    if (best < 0 || bestError > maxErrorMeters_) return false;
    for (int t : star) {
      alive_[static_cast<size_t>(t)] = false;
      Triangle moved = vertexTriangles[static_cast<size_t>(t)];
      if (std::find(moved.begin(), moved.end(), best) != moved.end()) continue;
      std::replace(moved.begin(), moved.end(), v, best);
      addTriangle(moved);
      for (int w : moved) dirty_[static_cast<size_t>(w)] = true;
    }
    return true;
  }

  // The largest error of the star's triangles with v moved onto u; INFINITY where one would fold
  // over. Stops once above `enough` (a better neighbour is already known).
  double collapseError(const std::vector<int>& star, int v, int u, double enough) const {
    double worst = 0;
    for (int t : star) {
      Triangle moved = vertexTriangles[static_cast<size_t>(t)];
      if (std::find(moved.begin(), moved.end(), u) != moved.end()) continue;
      std::replace(moved.begin(), moved.end(), v, u);
      const std::array<GridPoint, 3> corners{points_[static_cast<size_t>(moved[0])],
                                             points_[static_cast<size_t>(moved[1])],
                                             points_[static_cast<size_t>(moved[2])]};
      if (orient(corners[0], corners[1], corners[2]) <= 0) return INFINITY;
      const WorstSample sample = worstSampleIn(
          grid_, corners, {positionOf(moved[0]), positionOf(moved[1]), positionOf(moved[2])}, true);
      worst = std::max(worst, sample.errorMeters);
      if (worst > maxErrorMeters_ || worst >= enough) return INFINITY;
    }
    return worst;
  }

  const Grid& grid_;
  double maxErrorMeters_;
  std::vector<GridPoint> points_;
  int fixedVertices_;
  std::vector<Triangle> vertexTriangles;
  std::vector<bool> alive_;
  std::vector<std::vector<int>> incident_;
  std::vector<bool> dirty_;
};

// Heights as positions: the grid's place in samples, the height in metres. A triangle's point
// then lies over the sample exactly, so the distance is the vertical error.
std::vector<Position> heightPositions(const std::vector<double>& heightsMeters, uint32_t side) {
  std::vector<Position> positions;
  positions.reserve(heightsMeters.size());
  for (size_t i = 0; i < heightsMeters.size(); ++i) {
    positions.push_back(
        {static_cast<double>(i % side), -static_cast<double>(i / side), heightsMeters[i]});
  }
  return positions;
}

}  // namespace

namespace {

GridTin simplify(const Grid& grid, double maxErrorMeters) {
  const double tolerance = std::max(0.0, maxErrorMeters);
  GreedyInsertion insertion(grid, tolerance);
  insertion.run();
  Decimation decimation(grid, tolerance, insertion.points, insertion.vertexTriangles,
                        insertion.fixedVertices);
  decimation.run();
  return decimation.result();
}

// The largest distance over every sample (and, with betweenSamples, every edge crossing).
double maxDistance(const Grid& grid, const GridTin& tin) {
  const auto side = static_cast<uint32_t>(grid.side);
  const auto pointOf = [&](uint32_t vertex) {
    const uint32_t sample = tin.samples[vertex];
    return GridPoint{static_cast<int>(sample % side), static_cast<int>(side - 1 - sample / side)};
  };
  // Every sample must be covered: one no triangle holds counts as an infinite error.
  std::vector<double> errors(grid.positions.size(), INFINITY);
  double crossings = 0;
  for (size_t i = 0; i + 2 < tin.triangles.size(); i += 3) {
    const std::array<GridPoint, 3> v{pointOf(tin.triangles[i]), pointOf(tin.triangles[i + 1]),
                                     pointOf(tin.triangles[i + 2])};
    const std::array<Position, 3> corners{grid.positions[tin.samples[tin.triangles[i]]],
                                          grid.positions[tin.samples[tin.triangles[i + 1]]],
                                          grid.positions[tin.samples[tin.triangles[i + 2]]]};
    const int64_t area = orient(v[0], v[1], v[2]);
    if (area <= 0) return INFINITY;
    const double sag = sagMeters(grid, v);
    if (grid.betweenSamples) {
      crossings = std::max(crossings, worstEdgeCrossing(grid, v, corners).errorMeters + sag);
    }
    const int x0 = std::min({v[0].x, v[1].x, v[2].x}), x1 = std::max({v[0].x, v[1].x, v[2].x});
    const int y0 = std::min({v[0].y, v[1].y, v[2].y}), y1 = std::max({v[0].y, v[1].y, v[2].y});
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const GridPoint p{x, y};
        const std::array<int64_t, 3> w{orient(v[1], v[2], p), orient(v[2], v[0], p),
                                       orient(v[0], v[1], p)};
        if (w[0] < 0 || w[1] < 0 || w[2] < 0) continue;
        double& e = errors[grid.sampleOf(p)];
        const double error = distanceMeters(w, area, corners, grid.positionAt(x, y)) + sag;
        e = std::isinf(e) ? error : std::max(e, error);
      }
    }
  }
  return std::max(crossings, *std::max_element(errors.begin(), errors.end()));
}

}  // namespace

GridTin simplifyTileGrid(const std::vector<double>& heightsMeters,
                         const std::vector<double>& apronHeightsMeters,
                         const std::vector<std::array<double, 3>>& ecefMeters, uint32_t side,
                         double maxErrorMeters) {
  const std::vector<Position> positions = heightPositions(heightsMeters, side);
  return simplify(Grid{positions, static_cast<int>(side), true, &ecefMeters, &apronHeightsMeters},
                  maxErrorMeters);
}

GridTin simplifyGrid(const std::vector<double>& heightsMeters, uint32_t side,
                     double maxErrorMeters) {
  const std::vector<Position> positions = heightPositions(heightsMeters, side);
  return simplify(Grid{positions, static_cast<int>(side), false}, maxErrorMeters);
}

double maxTinErrorMeters(const std::vector<double>& heightsMeters, uint32_t side,
                         const GridTin& tin) {
  const std::vector<Position> positions = heightPositions(heightsMeters, side);
  return maxDistance(Grid{positions, static_cast<int>(side), false}, tin);
}

double maxTileTinErrorMeters(const std::vector<double>& heightsMeters,
                             const std::vector<std::array<double, 3>>& ecefMeters, uint32_t side,
                             const GridTin& tin) {
  const std::vector<Position> positions = heightPositions(heightsMeters, side);
  return maxDistance(Grid{positions, static_cast<int>(side), true, &ecefMeters}, tin);
}

}  // namespace globe::publish
