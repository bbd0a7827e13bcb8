#include "tiles3d/height_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geo/ecef.hpp"

namespace globe::tiles3d {
namespace {

constexpr float kNone = std::numeric_limits<float>::quiet_NaN();

// Whether triangle abc (any winding) meets the rectangle [x0, x1] × [y0, y1]: separating axes
// (the rectangle's two, then each edge's normal).
template <typename P>
bool meets(const P& a, const P& b, const P& c, double x0, double y0, double x1, double y1) {
  const P* v[3] = {&a, &b, &c};
  for (int e = 0; e < 3; ++e) {
    const P& p = *v[e];
    const P& q = *v[(e + 1) % 3];
    const P& r = *v[(e + 2) % 3];
    const double nx = q.lat - p.lat, ny = p.lon - q.lon;  // the edge's normal
    const double side = nx * (r.lon - p.lon) + ny * (r.lat - p.lat);
    if (side == 0) continue;  // degenerate: the bounding box decides
    bool allOutside = true;
    for (const double x : {x0, x1}) {
      for (const double y : {y0, y1}) {
        const double s = nx * (x - p.lon) + ny * (y - p.lat);
        if (s * side >= 0) allOutside = false;
      }
    }
    if (allOutside) return false;
  }
  return true;
}

}  // namespace

HeightGrid HeightGrid::rasterize(const TriangleMesh& mesh, const geo::Ellipsoid& ellipsoid,
                                 double cellMeters, uint32_t maxCellsPerSide) {
  HeightGrid grid;
  std::vector<Corner> corners;
  corners.reserve(mesh.positions.size());
  for (const glm::dvec3& p : mesh.positions) {
    const auto c = geo::ecefToCartographic(ellipsoid, p);
    if (!c) return grid;  // the geocentre or non-finite: nothing to stand on
    corners.push_back({c->longitudeRadians, c->latitudeRadians, c->heightMeters});
  }
  if (corners.size() < 3) return grid;
  // Across ±180°: longitudes unwrapped around the first vertex's.
  for (Corner& c : corners) {
    if (c.lon - corners[0].lon > std::numbers::pi) c.lon -= 2 * std::numbers::pi;
    if (corners[0].lon - c.lon > std::numbers::pi) c.lon += 2 * std::numbers::pi;
  }
  geo::GlobeRectangle r{corners[0].lon, corners[0].lat, corners[0].lon, corners[0].lat};
  for (const Corner& c : corners) {
    r.westRadians = std::min(r.westRadians, c.lon), r.eastRadians = std::max(r.eastRadians, c.lon);
    r.southRadians = std::min(r.southRadians, c.lat),
    r.northRadians = std::max(r.northRadians, c.lat);
  }
  const double radius = ellipsoid.semiMajorAxisMeters;
  const double cosLat = std::max(std::cos((r.southRadians + r.northRadians) / 2), 1e-6);
  auto cells = [&](double radians, double scale) {
    return static_cast<uint32_t>(std::clamp(std::ceil(radians * radius * scale / cellMeters), 1.0,
                                            static_cast<double>(maxCellsPerSide)));
  };
  grid.rectangle_ = r;
  grid.columns_ = cells(r.widthRadians(), cosLat);
  grid.rows_ = cells(r.heightRadians(), 1.0);
  grid.heightsMeters_.assign(size_t{grid.columns_} * grid.rows_, kNone);
  grid.setScales();
  grid.maximumMeters_ = -std::numeric_limits<double>::infinity();
  for (size_t t = 0; t + 2 < corners.size(); t += 3) {
    grid.addTriangle(corners[t], corners[t + 1], corners[t + 2]);
  }
  return grid;
}

void HeightGrid::addTriangle(const Corner& a, const Corner& b, const Corner& c) {
  // (A rectangle without width or height: one cell across it, any size holds it.)
  const double cellWidth = std::max(rectangle_.widthRadians() / columns_, 1e-300);
  const double cellHeight = std::max(rectangle_.heightRadians() / rows_, 1e-300);
  const double top = std::max({a.heightMeters, b.heightMeters, c.heightMeters});
  maximumMeters_ = std::max(maximumMeters_, top);
  // The plane h = h0 + hx·lon + hy·lat through the three, unless they stand edge-on from above.
  const double det = (b.lon - a.lon) * (c.lat - a.lat) - (c.lon - a.lon) * (b.lat - a.lat);
  const bool faceUp = std::fabs(det) > 1e-24;
  const double hx = faceUp ? ((b.heightMeters - a.heightMeters) * (c.lat - a.lat) -
                              (c.heightMeters - a.heightMeters) * (b.lat - a.lat)) /
                                 det
                           : 0;
  const double hy = faceUp ? ((c.heightMeters - a.heightMeters) * (b.lon - a.lon) -
                              (b.heightMeters - a.heightMeters) * (c.lon - a.lon)) /
                                 det
                           : 0;
  auto plane = [&](double lon, double lat) {
    return faceUp ? std::min(top, a.heightMeters + hx * (lon - a.lon) + hy * (lat - a.lat)) : top;
  };
  auto cellOf = [](double v, double origin, double size, uint32_t count) {
    return static_cast<uint32_t>(
        std::clamp(std::floor((v - origin) / size), 0.0, double(count - 1)));
  };
  const uint32_t c0 =
      cellOf(std::min({a.lon, b.lon, c.lon}), rectangle_.westRadians, cellWidth, columns_);
  const uint32_t c1 =
      cellOf(std::max({a.lon, b.lon, c.lon}), rectangle_.westRadians, cellWidth, columns_);
  const uint32_t r0 =
      cellOf(std::min({a.lat, b.lat, c.lat}), rectangle_.southRadians, cellHeight, rows_);
  const uint32_t r1 =
      cellOf(std::max({a.lat, b.lat, c.lat}), rectangle_.southRadians, cellHeight, rows_);
  for (uint32_t row = r0; row <= r1; ++row) {
    const double y0 = rectangle_.southRadians + row * cellHeight, y1 = y0 + cellHeight;
    for (uint32_t column = c0; column <= c1; ++column) {
      const double x0 = rectangle_.westRadians + column * cellWidth, x1 = x0 + cellWidth;
      if (!meets(a, b, c, x0, y0, x1, y1)) continue;
      const double h = std::max({plane(x0, y0), plane(x1, y0), plane(x0, y1), plane(x1, y1)});
      float& cell = heightsMeters_[size_t{row} * columns_ + column];
      float up = static_cast<float>(h);  // rounded up: never below
      if (up < h) up = std::nextafter(up, std::numeric_limits<float>::infinity());
      if (!(cell >= up)) cell = up;
    }
  }
}

HeightGrid HeightGrid::merge(std::span<const HeightGrid* const> grids, uint32_t maxCellsPerSide) {
  HeightGrid merged;
  geo::GlobeRectangle r{0, 0, 0, 0};
  double cellWidth = 1e300, cellHeight = 1e300;
  bool any = false;
  for (const HeightGrid* g : grids) {
    if (g->empty()) continue;
    const geo::GlobeRectangle& b = g->rectangle_;
    r = any ? geo::GlobeRectangle{std::min(r.westRadians, b.westRadians),
                                  std::min(r.southRadians, b.southRadians),
                                  std::max(r.eastRadians, b.eastRadians),
                                  std::max(r.northRadians, b.northRadians)}
            : b;
    any = true;
    if (b.widthRadians() > 0) cellWidth = std::min(cellWidth, b.widthRadians() / g->columns_);
    if (b.heightRadians() > 0) cellHeight = std::min(cellHeight, b.heightRadians() / g->rows_);
  }
  if (!any || r.widthRadians() > std::numbers::pi) return merged;
  auto cells = [&](double span, double cell) {
    return static_cast<uint32_t>(
        std::clamp(std::ceil(span / cell), 1.0, static_cast<double>(maxCellsPerSide)));
  };
  merged.rectangle_ = r;
  merged.columns_ = cells(r.widthRadians(), cellWidth);
  merged.rows_ = cells(r.heightRadians(), cellHeight);
  merged.heightsMeters_.assign(size_t{merged.columns_} * merged.rows_, kNone);
  merged.setScales();
  merged.maximumMeters_ = -std::numeric_limits<double>::infinity();
  const double mw = std::max(r.widthRadians() / merged.columns_, 1e-300);
  const double mh = std::max(r.heightRadians() / merged.rows_, 1e-300);
  auto range = [](double from, double to, double origin, double size, uint32_t count) {
    const auto first = std::clamp(std::floor((from - origin) / size), 0.0, double(count - 1));
    const auto last = std::clamp(std::ceil((to - origin) / size) - 1, first, double(count - 1));
    return std::pair{static_cast<uint32_t>(first), static_cast<uint32_t>(last)};
  };
  for (const HeightGrid* g : grids) {
    if (g->empty()) continue;
    merged.maximumMeters_ = std::max(merged.maximumMeters_, g->maximumMeters_);
    const geo::GlobeRectangle& b = g->rectangle_;
    const double gw = b.widthRadians() / g->columns_, gh = b.heightRadians() / g->rows_;
    for (uint32_t row = 0; row < g->rows_; ++row) {
      const auto [r0, r1] = range(b.southRadians + row * gh, b.southRadians + (row + 1) * gh,
                                  r.southRadians, mh, merged.rows_);
      for (uint32_t column = 0; column < g->columns_; ++column) {
        const float h = g->heightsMeters_[size_t{row} * g->columns_ + column];
        if (std::isnan(h)) continue;
        const auto [c0, c1] = range(b.westRadians + column * gw, b.westRadians + (column + 1) * gw,
                                    r.westRadians, mw, merged.columns_);
        for (uint32_t mr = r0; mr <= r1; ++mr) {
          for (uint32_t mc = c0; mc <= c1; ++mc) {
            float& cell = merged.heightsMeters_[size_t{mr} * merged.columns_ + mc];
            if (!(cell >= h)) cell = h;
          }
        }
      }
    }
  }
  return merged;
}

void HeightGrid::setScales() {
  const double w = rectangle_.widthRadians(), h = rectangle_.heightRadians();
  columnsPerRadian_ = w > 0 ? columns_ / w : 0.0;
  rowsPerRadian_ = h > 0 ? rows_ / h : 0.0;
}

}  // namespace globe::tiles3d
