// The highest surface of the 3D tile contents one frame draws, as collision reads it with the
// terrain: their height grids (height_grid.hpp) binned over the rectangle they cover, so a
// point reads the few grids of its bin, each in O(1). Immutable once made: a frame's collision
// keeps its snapshot while the next frame's selection makes another.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
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

  std::optional<double> heightAt(double longitudeRadians, double latitudeRadians) const;
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
