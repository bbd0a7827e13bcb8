#include "overlays/overlay_pick.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "overlays/drape_set.hpp"

namespace globe::overlays {
namespace {

constexpr double kMetersPerDegree = 111320.0;  // near enough for a click's tolerance

// A ring in metres on a plane tangent at the click: its first vertex taken the short way round
// from the click, each next one the short way from the one before (a ring across ±180° stays
// whole).
std::vector<std::pair<double, double>> projectRing(const std::vector<Position>& ring, double lon0,
                                                   double lat0) {
  const double metersPerLonDegree =
      kMetersPerDegree * std::max(std::cos(lat0 * M_PI / 180.0), 1e-6);
  std::vector<std::pair<double, double>> points;
  points.reserve(ring.size());
  double previous = lon0;
  for (const Position& p : ring) {
    double lon = p.longitudeDegrees;
    lon -= 360.0 * std::round((lon - previous) / 360.0);
    previous = lon;
    points.emplace_back((lon - lon0) * metersPerLonDegree,
                        (p.latitudeDegrees - lat0) * kMetersPerDegree);
  }
  return points;
}

double distanceToSegment(double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay;
  const double lengthSquared = dx * dx + dy * dy;
  const double t =
      lengthSquared > 0 ? std::clamp(-(ax * dx + ay * dy) / lengthSquared, 0.0, 1.0) : 0.0;
  return std::hypot(ax + t * dx, ay + t * dy);
}

bool ringNear(const std::vector<std::pair<double, double>>& ring, double tolerance) {
  for (size_t i = 0; i + 1 < ring.size(); ++i) {
    if (distanceToSegment(ring[i].first, ring[i].second, ring[i + 1].first, ring[i + 1].second) <=
        tolerance) {
      return true;
    }
  }
  return false;
}

// Even-odd crossing count of a ray from the origin (the click) towards +x.
bool ringCrossesOdd(const std::vector<std::pair<double, double>>& ring) {
  bool inside = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const auto [xi, yi] = ring[i];
    const auto [xj, yj] = ring[j];
    if ((yi > 0) != (yj > 0) && 0 < xj + (0 - yj) * (xi - xj) / (yi - yj)) inside = !inside;
  }
  return inside;
}

bool hits(const Geometry& geometry, double lon0, double lat0, double tolerance) {
  bool inside = false;
  for (const auto& ring : geometry.rings) {
    if (ring.size() < 2) continue;
    const auto projected = projectRing(ring, lon0, lat0);
    if (ringNear(projected, tolerance)) return true;
    if (geometry.kind == GeometryKind::Polygon && ring.size() >= 3) {
      inside ^= ringCrossesOdd(projected);
    }
  }
  return inside;
}

}  // namespace

std::optional<PlacemarkRef> pickDraped(
    std::span<const std::shared_ptr<const OverlayDocument>> documents, double longitudeDegrees,
    double latitudeDegrees, double toleranceMeters) {
  if (!std::isfinite(longitudeDegrees) || !std::isfinite(latitudeDegrees)) return std::nullopt;
  // Lines are drawn over polygons, each kind in file order: look from the top down.
  for (const bool lines : {true, false}) {
    for (size_t d = documents.size(); d-- > 0;) {
      if (!documents[d]) continue;
      const auto& placemarks = documents[d]->placemarks;
      for (size_t p = placemarks.size(); p-- > 0;) {
        if (!placemarks[p].visible) continue;
        for (const Geometry& geometry : placemarks[p].geometries) {
          if (!isDraped(geometry) || (geometry.kind == GeometryKind::LineString) != lines) {
            continue;
          }
          if (hits(geometry, longitudeDegrees, latitudeDegrees, toleranceMeters))
            return PlacemarkRef{d, p};
        }
      }
    }
  }
  return std::nullopt;
}

}  // namespace globe::overlays
