#include "terrain/tin_tile.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "geo/ecef.hpp"

namespace globe::terrain {
namespace {

// A barycentric weight this small puts the point on the opposite edge: that vertex does not
// bound the surface there (as the grid rule's row and column cases).
constexpr double kOnEdge = 1e-9;
// Four cells a triangle: a cell then meets two or three (a quantized-mesh tile has some hundreds
// to 2·64² triangles).
constexpr double kTrianglesPerCell = 0.25;
constexpr uint32_t kMaxCellsPerSide = 256;

}  // namespace

Result<TinTile> TinTile::build(const geo::GlobeRectangle& rectangle,
                               std::vector<TinVertex> vertices, std::vector<uint32_t> triangles,
                               const std::string& name) {
  if (triangles.empty() || triangles.size() % 3 != 0) {
    return makeError(name + ": a TIN tile needs whole triangles (" +
                     std::to_string(triangles.size()) + " indices)");
  }
  for (uint32_t index : triangles) {
    if (index >= vertices.size()) {
      return makeError(name + ": triangle vertex " + std::to_string(index) + " of " +
                       std::to_string(vertices.size()));
    }
  }
  for (const TinVertex& p : vertices) {
    if (!(p.u >= 0 && p.u <= 1 && p.v >= 0 && p.v <= 1 && std::isfinite(p.heightMeters))) {
      return makeError(name + ": a vertex off its tile or without a height");
    }
  }
  TinTile tile;
  tile.rectangle_ = rectangle;
  tile.uPerRadian_ = 1.0 / (rectangle.eastRadians - rectangle.westRadians);
  tile.vPerRadian_ = 1.0 / (rectangle.northRadians - rectangle.southRadians);
  tile.vertices_ = std::move(vertices);
  tile.maximumHeightMeters_ = -INFINITY, tile.minimumHeightMeters_ = INFINITY;
  for (const TinVertex& p : tile.vertices_) {
    tile.maximumHeightMeters_ = std::max(tile.maximumHeightMeters_, p.heightMeters);
    tile.minimumHeightMeters_ = std::min(tile.minimumHeightMeters_, p.heightMeters);
  }
  tile.triangles_ = std::move(triangles);
  tile.prepareTriangles();
  tile.buildCells();
  return tile;
}

void TinTile::prepareTriangles() {
  prepared_.clear();
  for (size_t k = 0; k < triangles_.size(); k += 3) {
    const TinVertex& a = vertices_[triangles_[k]];
    const TinVertex& b = vertices_[triangles_[k + 1]];
    const TinVertex& c = vertices_[triangles_[k + 2]];
    const double area = twiceSignedArea(a, b, c);
    // A degenerate triangle holds no point (its weight a is -1 everywhere): its neighbours hold
    // the points along it.
    Prepared p{-1, 0, 0, 0, 0, 0, 0, 0, 0};
    if (area != 0) {
      p.a0 = (b.u * c.v - c.u * b.v) / area, p.au = (b.v - c.v) / area, p.av = (c.u - b.u) / area;
      p.b0 = (c.u * a.v - a.u * c.v) / area, p.bu = (c.v - a.v) / area, p.bv = (a.u - c.u) / area;
    }
    p.ha = a.heightMeters, p.hb = b.heightMeters, p.hc = c.heightMeters;
    prepared_.push_back(p);
  }
}

void TinTile::buildCells() {
  const double wanted =
      std::ceil(std::sqrt(static_cast<double>(triangleCount()) / kTrianglesPerCell));
  cells_ = static_cast<uint32_t>(std::clamp(wanted, 1.0, double{kMaxCellsPerSide}));
  const double n = cells_;
  // Each triangle in every cell its bounding box meets, widened a hair so a point on a cell
  // line finds the triangles on both sides.
  auto cellRange = [&](double low, double high) {
    const auto first = static_cast<uint32_t>(std::clamp(std::floor(low * n - 1e-7), 0.0, n - 1));
    const auto last = static_cast<uint32_t>(std::clamp(std::floor(high * n + 1e-7), 0.0, n - 1));
    return std::array<uint32_t, 2>{first, last};
  };
  std::vector<uint32_t> counts(size_t{cells_} * cells_ + 1, 0);
  auto forEachCell = [&](uint32_t t, auto&& f) {
    const TinVertex& a = vertices_[triangles_[3 * t]];
    const TinVertex& b = vertices_[triangles_[3 * t + 1]];
    const TinVertex& c = vertices_[triangles_[3 * t + 2]];
    const auto columns = cellRange(std::min({a.u, b.u, c.u}), std::max({a.u, b.u, c.u}));
    const auto rows = cellRange(std::min({a.v, b.v, c.v}), std::max({a.v, b.v, c.v}));
    for (uint32_t row = rows[0]; row <= rows[1]; ++row) {
      for (uint32_t column = columns[0]; column <= columns[1]; ++column) f(row * cells_ + column);
    }
  };
  const auto count = static_cast<uint32_t>(triangleCount());
  for (uint32_t t = 0; t < count; ++t) forEachCell(t, [&](uint32_t cell) { ++counts[cell + 1]; });
  for (size_t i = 1; i < counts.size(); ++i) counts[i] += counts[i - 1];
  cellStart_ = counts;
  cellTriangles_.resize(counts.back());
  for (uint32_t t = 0; t < count; ++t)
    forEachCell(t, [&](uint32_t cell) { cellTriangles_[counts[cell]++] = t; });
}

bool TinTile::tryTriangle(uint32_t t, double u, double v, TinHeight& out) const {
  const Prepared& p = prepared_[t];
  const double wa = p.a0 + p.au * u + p.av * v;
  const double wb = p.b0 + p.bu * u + p.bv * v;
  const double wc = 1.0 - wa - wb;
  if (wa < -kOnEdge || wb < -kOnEdge || wc < -kOnEdge) return false;
  out.found = true;
  out.triangle = t;
  out.exactMeters = wa * p.ha + wb * p.hb + wc * p.hc;
  // The vertices bounding the surface at the point: all three inside, the edge's two on an
  // edge, the one on a vertex.
  double highest = out.exactMeters;
  if (wa > kOnEdge) highest = std::max(highest, p.ha);
  if (wb > kOnEdge) highest = std::max(highest, p.hb);
  if (wc > kOnEdge) highest = std::max(highest, p.hc);
  out.conservativeMeters = highest;
  return true;
}

TinHeight TinTile::heightAt(double longitudeRadians, double latitudeRadians) const {
  const double u = (longitudeRadians - rectangle_.westRadians) * uPerRadian_;
  const double v = (latitudeRadians - rectangle_.southRadians) * vPerRadian_;
  TinHeight result;
  if (!(u >= -kOnEdge && u <= 1 + kOnEdge && v >= -kOnEdge && v <= 1 + kOnEdge)) return result;
  const auto last = static_cast<int>(cells_) - 1;
  const int column = std::min(std::max(static_cast<int>(u * cells_), 0), last);
  const int row = std::min(std::max(static_cast<int>(v * cells_), 0), last);
  const size_t cell = static_cast<size_t>(row) * cells_ + static_cast<size_t>(column);
  for (uint32_t k = cellStart_[cell], end = cellStart_[cell + 1]; k < end; ++k) {
    if (tryTriangle(cellTriangles_[k], u, v, result)) return result;
  }
  return result;
}

glm::dvec3 TinTile::vertexEcefMeters(const geo::Ellipsoid& ellipsoid, uint32_t k) const {
  const TinVertex& p = vertices_[k];
  const geo::GlobeRectangle& r = rectangle_;
  auto between = [](double low, double high, double f) {
    return f <= 0 ? low : f >= 1 ? high : low + f * (high - low);
  };
  return geo::cartographicToEcef(ellipsoid,
                                 {between(r.westRadians, r.eastRadians, p.u),
                                  between(r.southRadians, r.northRadians, p.v), p.heightMeters});
}

std::array<glm::dvec3, 3> TinTile::triangleEcefMeters(const geo::Ellipsoid& ellipsoid, uint32_t t,
                                                      const glm::dvec3& origin) const {
  return {vertexEcefMeters(ellipsoid, triangles_[3 * t]) - origin,
          vertexEcefMeters(ellipsoid, triangles_[3 * t + 1]) - origin,
          vertexEcefMeters(ellipsoid, triangles_[3 * t + 2]) - origin};
}

bool TinTile::setNormals(std::vector<glm::vec3> normals) {
  if (normals.size() != vertices_.size()) return false;
  normals_ = std::move(normals);
  return true;
}

void TinTile::forEachTriangleNear(double u0, double v0, double u1, double v1,
                                  const std::function<void(uint32_t)>& visit) const {
  const auto last = static_cast<int>(cells_) - 1;
  auto cellOf = [&](double f) {
    return std::min(std::max(static_cast<int>(std::floor(f * cells_)), 0), last);
  };
  const int c0 = cellOf(u0), c1 = cellOf(u1), r0 = cellOf(v0), r1 = cellOf(v1);
  std::vector<uint8_t> seen(triangleCount(), 0);
  for (int row = r0; row <= r1; ++row) {
    for (int column = c0; column <= c1; ++column) {
      const size_t cell = static_cast<size_t>(row) * cells_ + static_cast<size_t>(column);
      for (uint32_t k = cellStart_[cell], end = cellStart_[cell + 1]; k < end; ++k) {
        const uint32_t t = cellTriangles_[k];
        if (seen[t] == 0) visit(t);
        seen[t] = 1;
      }
    }
  }
}

}  // namespace globe::terrain
