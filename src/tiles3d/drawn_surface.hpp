// The highest surface of the 3D tile contents one frame draws, as collision reads it with the
// terrain: their height grids (height_grid.hpp) binned over the rectangle they cover, so a
// point reads the few grids of its bin, each in O(1). Immutable once made: a frame's collision
// keeps its snapshot while the next frame's selection makes another.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "geo/globe_rectangle.hpp"
#include "tiles3d/loaded_content.hpp"

namespace globe::tiles3d {

class DrawnSurface {
 public:
  static constexpr uint32_t kBinsPerSide = 64;
  DrawnSurface() = default;
  explicit DrawnSurface(std::vector<std::shared_ptr<const LoadedContent>> contents);

  // Inline: collision's probes read it at every point they test.
  std::optional<double> heightAt(double longitudeRadians, double latitudeRadians) const {
    if (contents_.empty()) return std::nullopt;
    double x = longitudeRadians - rectangle_.westRadians;
    if (x < 0) x += 2 * std::numbers::pi;  // the union unwrapped across ±180° as its grids are
    const double y = latitudeRadians - rectangle_.southRadians;
    if (!(x <= rectangle_.widthRadians() && y >= 0 && y <= rectangle_.heightRadians())) {
      return std::nullopt;
    }
    const uint32_t column = std::min(static_cast<uint32_t>(x * binsPerRadianX_), binsX_ - 1);
    const uint32_t row = std::min(static_cast<uint32_t>(y * binsPerRadianY_), binsY_ - 1);
    const size_t bin = size_t{row} * binsX_ + column;
    float best = std::numeric_limits<float>::quiet_NaN();
    for (uint32_t k = binStart_[bin]; k < binStart_[bin + 1]; ++k) {
      const float h = binGrids_[k]->cellHeightMeters(longitudeRadians, latitudeRadians);
      if (!(h <= best)) best = std::isnan(h) ? best : h;  // NaN: none there
    }
    if (std::isnan(best)) return std::nullopt;
    return best;
  }
  double maximumHeightMeters() const { return maximumMeters_; }
  size_t contentCount() const { return contents_.size(); }

 private:
  std::vector<std::shared_ptr<const LoadedContent>> contents_;
  geo::GlobeRectangle rectangle_{0, 0, 0, 0};
  double binsPerRadianX_ = 0, binsPerRadianY_ = 0;
  uint32_t binsX_ = 0, binsY_ = 0;
  std::vector<uint32_t> binStart_;           // binsX_·binsY_ + 1 offsets into binGrids_
  std::vector<const HeightGrid*> binGrids_;  // the grids of each bin, bin after bin
  double maximumMeters_ = -std::numeric_limits<double>::infinity();
};

}  // namespace globe::tiles3d
