#include "buildings/roof_triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "overlays/ring_triangulation.hpp"

namespace globe::buildings {
namespace {

double cross(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}
double cross(const glm::dvec2& u, const glm::dvec2& v) { return u.x * v.y - u.y * v.x; }

// Whether segments pq and rs cross at a point inside both (touching ends do not count).
bool properlyCross(const glm::dvec2& p, const glm::dvec2& q, const glm::dvec2& r,
                   const glm::dvec2& s) {
  const double d1 = cross(p, q, r), d2 = cross(p, q, s), d3 = cross(r, s, p), d4 = cross(r, s, q);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

struct Polygon {
  std::vector<glm::dvec2> points;  // every ring's vertices, in order
  std::vector<uint32_t> loop;      // the outer ring with the holes bridged in (indices repeat)
};

// Whether direction d from loop vertex k points into the (counter-clockwise) polygon.
bool locallyInside(const Polygon& p, size_t k, const glm::dvec2& d) {
  const size_t n = p.loop.size();
  const glm::dvec2 v = p.points[p.loop[k]];
  const glm::dvec2 prev = p.points[p.loop[(k + n - 1) % n]] - v;
  const glm::dvec2 next = p.points[p.loop[(k + 1) % n]] - v;
  if (cross(-prev, next) >= 0) return cross(next, d) > 0 && cross(d, prev) > 0;  // convex
  return !(cross(prev, d) >= 0 && cross(d, next) >= 0);                          // reflex
}

// Joins the hole (indices, clockwise) to the loop at the nearest loop vertex it sees.
void bridge(Polygon& p, const std::vector<uint32_t>& hole,
            const std::vector<std::vector<uint32_t>>& holes) {
  size_t m = 0;
  for (size_t i = 1; i < hole.size(); ++i) {
    if (p.points[hole[i]].x > p.points[hole[m]].x) m = i;
  }
  const glm::dvec2 from = p.points[hole[m]];
  std::vector<size_t> order(p.loop.size());
  std::iota(order.begin(), order.end(), size_t{0});
  const auto distance = [&](size_t k) {
    const glm::dvec2 d = p.points[p.loop[k]] - from;
    return d.x * d.x + d.y * d.y;
  };
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return distance(a) != distance(b) ? distance(a) < distance(b) : a < b;
  });
  const auto blocked = [&](const glm::dvec2& to, const std::vector<uint32_t>& ring) {
    for (size_t i = 0; i < ring.size(); ++i) {
      if (properlyCross(from, to, p.points[ring[i]], p.points[ring[(i + 1) % ring.size()]])) {
        return true;
      }
    }
    return false;
  };
  size_t at = order.front();
  for (size_t k : order) {
    const glm::dvec2 to = p.points[p.loop[k]];
    if (!locallyInside(p, k, from - to) || blocked(to, p.loop)) continue;
    if (std::any_of(holes.begin(), holes.end(), [&](const auto& h) { return blocked(to, h); })) {
      continue;
    }
    at = k;
    break;
  }
  std::vector<uint32_t> spliced(p.loop.begin(), p.loop.begin() + static_cast<long>(at) + 1);
  for (size_t i = 0; i <= hole.size(); ++i) spliced.push_back(hole[(m + i) % hole.size()]);
  spliced.insert(spliced.end(), p.loop.begin() + static_cast<long>(at), p.loop.end());
  p.loop = std::move(spliced);
}

bool inside(const glm::dvec2& q, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return cross(a, b, q) >= 0 && cross(b, c, q) >= 0 && cross(c, a, q) >= 0;
}

// Ear clipping of the bridged loop; a vertex that coincides with a corner never blocks an ear
// (the bridges' ends repeat). Where no ear is left, any convex corner is cut, then none.
std::vector<uint32_t> clipEars(const Polygon& p) {
  std::vector<uint32_t> triangles;
  std::vector<uint32_t> left = p.loop;
  size_t misses = 0;
  bool relaxed = false;
  for (size_t i = 0; left.size() > 3;) {
    const size_t n = left.size();
    const uint32_t a = left[(i + n - 1) % n], b = left[i % n], c = left[(i + 1) % n];
    const glm::dvec2 pa = p.points[a], pb = p.points[b], pc = p.points[c];
    bool ear = cross(pa, pb, pc) > 0;
    for (size_t k = 0; ear && !relaxed && k < n; ++k) {
      const glm::dvec2 q = p.points[left[k]];
      if (q != pa && q != pb && q != pc && inside(q, pa, pb, pc)) ear = false;
    }
    if (ear) {
      triangles.insert(triangles.end(), {a, b, c});
      left.erase(left.begin() + static_cast<long>(i % n));
      misses = 0;
    } else if (++misses >= n) {
      if (relaxed) break;
      relaxed = true;
      misses = 0;
    } else {
      ++i;
    }
  }
  if (left.size() == 3 && cross(p.points[left[0]], p.points[left[1]], p.points[left[2]]) > 0) {
    triangles.insert(triangles.end(), {left[0], left[1], left[2]});
  }
  return triangles;
}

}  // namespace

std::vector<uint32_t> triangulatePolygon(std::span<const PlaneRing> rings) {
  if (rings.empty() || rings.front().size() < 3) return {};
  if (rings.size() == 1) {
    const std::vector<size_t> t = overlays::triangulateRing(rings.front());  // counter-clockwise
    return {t.begin(), t.end()};
  }
  Polygon p;
  std::vector<std::vector<uint32_t>> holes;
  for (size_t r = 0; r < rings.size(); ++r) {
    std::vector<uint32_t> indices(rings[r].size());
    std::iota(indices.begin(), indices.end(), static_cast<uint32_t>(p.points.size()));
    p.points.insert(p.points.end(), rings[r].begin(), rings[r].end());
    const bool counterClockwise = signedAreaSquareMeters(rings[r]) > 0;
    if ((r == 0) != counterClockwise) std::reverse(indices.begin(), indices.end());
    if (r == 0) {
      p.loop = std::move(indices);
    } else if (indices.size() >= 3) {
      holes.push_back(std::move(indices));
    }
  }
  const auto maxX = [&](const std::vector<uint32_t>& h) {
    double x = -1e300;
    for (uint32_t i : h) x = std::max(x, p.points[i].x);
    return x;
  };
  std::sort(holes.begin(), holes.end(),
            [&](const auto& a, const auto& b) { return maxX(a) > maxX(b); });
  for (size_t h = 0; h < holes.size(); ++h) {
    const std::vector<std::vector<uint32_t>> rest(holes.begin() + static_cast<long>(h) + 1,
                                                  holes.end());
    bridge(p, holes[h], rest);
  }
  return clipEars(p);
}

double signedAreaSquareMeters(const PlaneRing& ring) {
  double area = 0;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    area += ring[j].x * ring[i].y - ring[i].x * ring[j].y;
  }
  return area / 2;
}

double polygonAreaSquareMeters(std::span<const PlaneRing> rings) {
  double area = 0;
  for (size_t r = 0; r < rings.size(); ++r) {
    const double a = std::abs(signedAreaSquareMeters(rings[r]));
    area += r == 0 ? a : -a;
  }
  return area;
}

}  // namespace globe::buildings
