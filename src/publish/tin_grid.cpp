#include "publish/tin_grid.hpp"

#include <algorithm>
#include <utility>

namespace globe::publish::tin {

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

}  // namespace globe::publish::tin
