#include "tiles3d/bounding_sphere.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "geo/ecef.hpp"

namespace globe::tiles3d {
namespace {

// Samples a region's edge takes at each height: enough that its bulge between them is small.
constexpr int kRegionSamples = 9;

Result<std::vector<double>> numbers(const nlohmann::json& j, size_t count, const std::string& name,
                                    const char* kind) {
  if (!j.is_array() || j.size() != count)
    return makeError(name + ": a bounding " + kind + " of other than " + std::to_string(count) +
                     " numbers");
  std::vector<double> out;
  for (const auto& v : j) {
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      return makeError(name + ": a bounding " + kind + " that is not finite");
    out.push_back(v.get<double>());
  }
  return out;
}

// The largest factor the transform's linear part stretches a length by (its columns' lengths
// summed in quadrature bound it from above).
double largestScale(const glm::dmat4& m) {
  const glm::dvec3 x(m[0]), y(m[1]), z(m[2]);
  return std::sqrt(glm::dot(x, x) + glm::dot(y, y) + glm::dot(z, z));
}

BoundingSphere sphereOfBox(const std::vector<double>& b, const glm::dmat4& m) {
  const glm::dmat3 linear(m);
  const glm::dvec3 center = glm::dvec3(m * glm::dvec4(b[0], b[1], b[2], 1.0));
  const std::array<glm::dvec3, 3> axes{linear * glm::dvec3(b[3], b[4], b[5]),
                                       linear * glm::dvec3(b[6], b[7], b[8]),
                                       linear * glm::dvec3(b[9], b[10], b[11])};
  double radius = 0;
  for (int corner = 0; corner < 8; ++corner) {
    glm::dvec3 offset(0.0);
    for (int a = 0; a < 3; ++a) offset += ((corner >> a) & 1 ? 1.0 : -1.0) * axes[a];
    radius = std::max(radius, glm::length(offset));
  }
  return {center, radius};
}

Result<BoundingSphere> sphereOfRegion(const std::vector<double>& r, const geo::Ellipsoid& e,
                                      const std::string& name) {
  const double west = r[0], south = r[1], east = r[2] < r[0] ? r[2] + 2 * M_PI : r[2];
  const double north = r[3], low = r[4], high = r[5];
  if (south > north || low > high || south < -M_PI / 2 || north > M_PI / 2)
    return makeError(name + ": a bounding region that is empty or past the poles");
  std::vector<glm::dvec3> points;
  for (int i = 0; i < kRegionSamples; ++i) {
    for (int j = 0; j < kRegionSamples; ++j) {
      const double lon = west + (east - west) * i / (kRegionSamples - 1);
      const double lat = south + (north - south) * j / (kRegionSamples - 1);
      for (const double h : {low, high})
        points.push_back(geo::cartographicToEcef(e, {lon, lat, h}));
    }
  }
  glm::dvec3 lo(points[0]), hi(points[0]);
  for (const glm::dvec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::dvec3 center = (lo + hi) / 2.0;
  double radius = 0;
  for (const glm::dvec3& p : points) radius = std::max(radius, glm::length(p - center));
  // An arc of angle a between samples bulges R·(1 − cos(a/2)) past their chord.
  const double step = std::max(east - west, north - south) / (kRegionSamples - 1);
  radius += (e.semiMajorAxisMeters + std::max(high, 0.0)) * (1 - std::cos(step / 2));
  return BoundingSphere{center, radius};
}

}  // namespace

double BoundingSphere::distanceMeters(const glm::dvec3& point) const {
  if (!std::isfinite(radiusMeters)) return 0;
  return std::max(0.0, glm::length(point - centerEcefMeters) - radiusMeters);
}

Result<BoundingSphere> boundingSphereOf(const nlohmann::json& volume, const glm::dmat4& transform,
                                        const geo::Ellipsoid& ellipsoid, const std::string& name) {
  if (!volume.is_object()) return BoundingSphere{};
  if (const auto box = volume.find("box"); box != volume.end()) {
    auto b = numbers(*box, 12, name, "box");
    if (!b) return Error{b.error()};
    return sphereOfBox(*b, transform);
  }
  if (const auto region = volume.find("region"); region != volume.end()) {
    auto r = numbers(*region, 6, name, "region");
    if (!r) return Error{r.error()};
    return sphereOfRegion(*r, ellipsoid, name);
  }
  if (const auto sphere = volume.find("sphere"); sphere != volume.end()) {
    auto s = numbers(*sphere, 4, name, "sphere");
    if (!s) return Error{s.error()};
    if ((*s)[3] < 0) return makeError(name + ": a bounding sphere of negative radius");
    const glm::dvec3 center(transform * glm::dvec4((*s)[0], (*s)[1], (*s)[2], 1.0));
    return BoundingSphere{center, (*s)[3] * largestScale(transform)};
  }
  return BoundingSphere{};  // an extension's volume (S2, ...): always in view
}

}  // namespace globe::tiles3d
