#include "overlays/ring_triangulation.hpp"

#include <algorithm>
#include <numeric>

namespace globe::overlays {
namespace {

double cross(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool inTriangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b,
                const glm::dvec2& c) {
  return cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0;
}

}  // namespace

std::vector<size_t> triangulateRing(std::span<const glm::dvec2> ring) {
  std::vector<size_t> triangles;
  if (ring.size() < 3) return triangles;
  std::vector<size_t> remaining(ring.size());
  std::iota(remaining.begin(), remaining.end(), size_t{0});
  // Counter-clockwise order makes every ear a left turn.
  double area = 0;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    area += ring[j].x * ring[i].y - ring[i].x * ring[j].y;
  }
  if (area < 0) std::reverse(remaining.begin(), remaining.end());
  size_t misses = 0;
  for (size_t i = 0; remaining.size() > 3 && misses < remaining.size();) {
    const size_t n = remaining.size();
    const size_t a = remaining[(i + n - 1) % n], b = remaining[i % n], c = remaining[(i + 1) % n];
    bool ear = cross(ring[a], ring[b], ring[c]) > 0;
    for (size_t k = 0; ear && k < n; ++k) {
      const size_t p = remaining[k];
      if (p != a && p != b && p != c && inTriangle(ring[p], ring[a], ring[b], ring[c])) {
        ear = false;
      }
    }
    if (ear) {
      triangles.insert(triangles.end(), {a, b, c});
      remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(i % n));
      misses = 0;
    } else {
      ++i;
      ++misses;
    }
  }
  if (remaining.size() == 3 &&
      cross(ring[remaining[0]], ring[remaining[1]], ring[remaining[2]]) > 0) {
    triangles.insert(triangles.end(), {remaining[0], remaining[1], remaining[2]});
  }
  return triangles;
}

}  // namespace globe::overlays
