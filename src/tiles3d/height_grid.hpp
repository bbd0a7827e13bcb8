// A 3D tile's drawn surface seen from above: the highest point of its triangles in each cell of
// a longitude/latitude grid over the rectangle they cover (none where no triangle lies), built
// once where the content loads. Conservative: a cell never reads below a triangle that meets it
// (the triangle's plane at the cell's corners, capped by its highest vertex), so QOTCD reading it
// in O(1) keeps the camera above every roof it draws.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "geo/ellipsoid.hpp"
#include "geo/globe_rectangle.hpp"
#include "tiles3d/triangle_mesh.hpp"

namespace globe::tiles3d {

class HeightGrid {
 public:
  // Cells about `cellMeters` wide, at most `maxCellsPerSide` a side. An empty mesh: no cells.
  static HeightGrid rasterize(const TriangleMesh& ecefTriangles, const geo::Ellipsoid& ellipsoid,
                              double cellMeters, uint32_t maxCellsPerSide);

  // One grid holding the highest of several (a tileset's drawn contents), so a point reads one
  // cell: over their rectangles' union with cells as fine as the finest of theirs (at most
  // maxCellsPerSide a side), each cell the highest of every cell of theirs it overlaps (still
  // never below). Empty when they are all empty or span more than half the globe.
  static HeightGrid merge(std::span<const HeightGrid* const> grids, uint32_t maxCellsPerSide);

  // The highest surface over the cell holding the point; nullopt off the grid or where no
  // triangle lies.
  std::optional<double> heightAt(double longitudeRadians, double latitudeRadians) const {
    const float h = cellHeightMeters(longitudeRadians, latitudeRadians);
    return std::isnan(h) ? std::nullopt : std::optional<double>(h);
  }
  // The same, NaN for none: inline, as the per-frame probes read it.
  float cellHeightMeters(double longitudeRadians, double latitudeRadians) const {
    if (heightsMeters_.empty()) return std::numeric_limits<float>::quiet_NaN();
    double x = longitudeRadians - rectangle_.westRadians;
    if (x < 0) x += 2 * std::numbers::pi;  // a grid unwrapped across ±180°
    const double y = latitudeRadians - rectangle_.southRadians;
    if (!(x <= rectangle_.widthRadians() && y >= 0 && y <= rectangle_.heightRadians())) {
      return std::numeric_limits<float>::quiet_NaN();
    }
    const uint32_t column = std::min(static_cast<uint32_t>(x * columnsPerRadian_), columns_ - 1);
    const uint32_t row = std::min(static_cast<uint32_t>(y * rowsPerRadian_), rows_ - 1);
    return heightsMeters_[size_t{row} * columns_ + column];
  }

  bool empty() const { return heightsMeters_.empty(); }
  const geo::GlobeRectangle& rectangle() const { return rectangle_; }
  uint32_t columns() const { return columns_; }
  uint32_t rows() const { return rows_; }
  double maximumHeightMeters() const { return maximumMeters_; }
  size_t sizeBytes() const { return heightsMeters_.size() * sizeof(float); }

 private:
  struct Corner {
    double lon, lat, heightMeters;
  };
  void addTriangle(const Corner& a, const Corner& b, const Corner& c);
  void setScales();

  geo::GlobeRectangle rectangle_{0, 0, 0, 0};
  uint32_t columns_ = 0, rows_ = 0;
  double columnsPerRadian_ = 0, rowsPerRadian_ = 0;  // 0 across a rectangle without extent
  double maximumMeters_ = 0;
  std::vector<float> heightsMeters_;  // row-major from the south-west; NaN: none
};

}  // namespace globe::tiles3d
