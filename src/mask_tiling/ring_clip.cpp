#include "mask_tiling/ring_clip.hpp"

#include <algorithm>

namespace globe::mask_tiling {
namespace {

// One Sutherland–Hodgman pass: keeps the half-plane where inside(p); a crossing vertex is placed
// exactly on the side (its clipped coordinate is the side's value, so runsAlongSides can test it
// with ==).
template <typename Inside, typename Cross>
Ring clipSide(const Ring& ring, Inside inside, Cross cross) {
  Ring out;
  out.reserve(ring.size() + 4);
  for (size_t i = 0; i < ring.size(); ++i) {
    const glm::dvec2& a = ring[i];
    const glm::dvec2& b = ring[(i + 1) % ring.size()];
    const bool aIn = inside(a), bIn = inside(b);
    if (aIn) out.push_back(a);
    if (aIn != bIn) out.push_back(cross(a, b));
  }
  return out;
}

glm::dvec2 atLongitude(const glm::dvec2& a, const glm::dvec2& b, double longitude) {
  const double t = (longitude - a.x) / (b.x - a.x);
  return {longitude, a.y + t * (b.y - a.y)};
}

glm::dvec2 atLatitude(const glm::dvec2& a, const glm::dvec2& b, double latitude) {
  const double t = (latitude - a.y) / (b.y - a.y);
  return {a.x + t * (b.x - a.x), latitude};
}

}  // namespace

RectangleDegrees boundsOf(const Ring& ring) {
  RectangleDegrees bounds{1e300, 1e300, -1e300, -1e300};
  for (const glm::dvec2& p : ring) {
    bounds.west = std::min(bounds.west, p.x);
    bounds.east = std::max(bounds.east, p.x);
    bounds.south = std::min(bounds.south, p.y);
    bounds.north = std::max(bounds.north, p.y);
  }
  return bounds;
}

Ring clipRing(const Ring& ring, const RectangleDegrees& r) {
  if (ring.size() < 3) return {};
  const RectangleDegrees bounds = boundsOf(ring);
  if (!bounds.intersects(r)) return {};
  if (bounds.west >= r.west && bounds.east <= r.east && bounds.south >= r.south &&
      bounds.north <= r.north) {
    return ring;  // wholly inside
  }
  Ring out = ring;
  if (bounds.west < r.west) {
    out = clipSide(
        out, [&](const glm::dvec2& p) { return p.x >= r.west; },
        [&](const glm::dvec2& a, const glm::dvec2& b) { return atLongitude(a, b, r.west); });
  }
  if (bounds.east > r.east && out.size() >= 3) {
    out = clipSide(
        out, [&](const glm::dvec2& p) { return p.x <= r.east; },
        [&](const glm::dvec2& a, const glm::dvec2& b) { return atLongitude(a, b, r.east); });
  }
  if (bounds.south < r.south && out.size() >= 3) {
    out = clipSide(
        out, [&](const glm::dvec2& p) { return p.y >= r.south; },
        [&](const glm::dvec2& a, const glm::dvec2& b) { return atLatitude(a, b, r.south); });
  }
  if (bounds.north > r.north && out.size() >= 3) {
    out = clipSide(
        out, [&](const glm::dvec2& p) { return p.y <= r.north; },
        [&](const glm::dvec2& a, const glm::dvec2& b) { return atLatitude(a, b, r.north); });
  }
  if (out.size() < 3) return {};
  return out;
}

bool runsAlongSides(const Ring& clipped, const RectangleDegrees& r) {
  auto sides = [&](const glm::dvec2& p) {
    return (p.x == r.west ? 1 : 0) | (p.x == r.east ? 2 : 0) | (p.y == r.south ? 4 : 0) |
           (p.y == r.north ? 8 : 0);
  };
  for (size_t i = 0; i < clipped.size(); ++i) {
    if ((sides(clipped[i]) & sides(clipped[(i + 1) % clipped.size()])) == 0) return false;
  }
  return true;
}

}  // namespace globe::mask_tiling
