#include "terrain/tin_clip.hpp"

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "geo/tiling_scheme.hpp"

namespace globe::terrain {
namespace {

using Polygon = std::vector<TinVertex>;

// Keeps the part of the polygon where side(p) >= 0 (Sutherland–Hodgman), the cut points on the
// line exactly (`onLine` sets the coordinate the line fixes).
template <typename Side, typename OnLine>
Polygon clip(const Polygon& in, Side side, OnLine onLine) {
  Polygon out;
  for (size_t k = 0; k < in.size(); ++k) {
    const TinVertex& a = in[k];
    const TinVertex& b = in[(k + 1) % in.size()];
    const double sa = side(a), sb = side(b);
    if (sa >= 0) out.push_back(a);
    if ((sa >= 0) != (sb >= 0)) {
      const double t = sa / (sa - sb);
      TinVertex cut{a.u + t * (b.u - a.u), a.v + t * (b.v - a.v),
                    a.heightMeters + t * (b.heightMeters - a.heightMeters)};
      onLine(cut);
      out.push_back(cut);
    }
  }
  return out;
}

}  // namespace

std::shared_ptr<const TinTile> childTin(const TinTile& parent, const geo::TileId& child) {
  const double u0 = (child.x & 1U) ? 0.5 : 0.0;
  const double v0 = (child.y & 1U) ? 0.0 : 0.5;  // rows grow south: an even row is the north half
  const double u1 = u0 + 0.5, v1 = v0 + 0.5;
  std::vector<TinVertex> vertices;
  std::vector<uint32_t> triangles;
  std::map<std::pair<double, double>, uint32_t> index;  // shared vertices once
  auto vertexOf = [&](const TinVertex& p) {
    TinVertex c{(p.u - u0) * 2.0, (p.v - v0) * 2.0, p.heightMeters};
    const auto [it, added] = index.try_emplace({c.u, c.v}, static_cast<uint32_t>(vertices.size()));
    if (added) vertices.push_back(c);
    return it->second;
  };
  const std::vector<TinVertex>& p = parent.vertices();
  const std::vector<uint32_t>& t = parent.triangles();
  for (size_t k = 0; k + 2 < t.size(); k += 3) {
    Polygon polygon{p[t[k]], p[t[k + 1]], p[t[k + 2]]};
    polygon = clip(
        polygon, [&](const TinVertex& q) { return q.u - u0; }, [&](TinVertex& q) { q.u = u0; });
    polygon = clip(
        polygon, [&](const TinVertex& q) { return u1 - q.u; }, [&](TinVertex& q) { q.u = u1; });
    polygon = clip(
        polygon, [&](const TinVertex& q) { return q.v - v0; }, [&](TinVertex& q) { q.v = v0; });
    polygon = clip(
        polygon, [&](const TinVertex& q) { return v1 - q.v; }, [&](TinVertex& q) { q.v = v1; });
    if (polygon.size() < 3) continue;
    std::vector<uint32_t> ids;
    for (const TinVertex& q : polygon) ids.push_back(vertexOf(q));
    for (size_t f = 1; f + 1 < ids.size(); ++f) {  // a fan: the clipped polygon is convex
      const TinVertex &a = vertices[ids[0]], &b = vertices[ids[f]], &c = vertices[ids[f + 1]];
      if (std::abs(twiceSignedArea(a, b, c)) > 1e-14)
        triangles.insert(triangles.end(), {ids[0], ids[f], ids[f + 1]});
    }
  }
  if (triangles.empty()) return nullptr;
  auto built = TinTile::build(geo::GeographicTilingScheme::tileRectangle(child),
                              std::move(vertices), std::move(triangles), geo::tileName(child));
  if (!built) return nullptr;
  return std::make_shared<const TinTile>(std::move(*built));
}

}  // namespace globe::terrain
