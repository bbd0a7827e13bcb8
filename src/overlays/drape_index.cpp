// A uniform grid of about one cell per shape (at most 512 x 512) over the shapes' bounds; a shape
// is listed in every cell its box covers, or, covering more than kWideCells, once among the wide.
#include "overlays/drape_index.hpp"

#include <algorithm>
#include <cmath>

namespace globe::overlays {
namespace {

constexpr int kMaximumSide = 512;
constexpr int64_t kWideCells = 256;

}  // namespace

DrapeIndex::DrapeIndex(std::span<const DrapedShape> shapes) {
  if (shapes.empty()) return;
  bounds_ = shapes.front().box;
  for (const DrapedShape& shape : shapes) {
    if (!std::isfinite(shape.box.west + shape.box.east + shape.box.south + shape.box.north))
      continue;
    bounds_ = {std::min(bounds_.west, shape.box.west), std::min(bounds_.south, shape.box.south),
               std::max(bounds_.east, shape.box.east), std::max(bounds_.north, shape.box.north)};
  }
  side_ = std::clamp(static_cast<int>(std::ceil(std::sqrt(static_cast<double>(shapes.size())))), 1,
                     kMaximumSide);
  cellWidth_ = std::max(1e-9, (bounds_.east - bounds_.west) / side_);
  cellHeight_ = std::max(1e-9, (bounds_.north - bounds_.south) / side_);
  cells_.resize(static_cast<size_t>(side_) * side_);
  for (size_t i = 0; i < shapes.size(); ++i) {
    const DegreesBox& box = shapes[i].box;
    const auto index = static_cast<uint32_t>(i);
    if (!(std::isfinite(box.west) && std::isfinite(box.east) && std::isfinite(box.south) &&
          std::isfinite(box.north))) {
      wide_.push_back(index);  // never placed by arithmetic on a NaN
      continue;
    }
    const int c0 =
        std::clamp(static_cast<int>((box.west - bounds_.west) / cellWidth_), 0, side_ - 1);
    const int c1 =
        std::clamp(static_cast<int>((box.east - bounds_.west) / cellWidth_), 0, side_ - 1);
    const int r0 =
        std::clamp(static_cast<int>((box.south - bounds_.south) / cellHeight_), 0, side_ - 1);
    const int r1 =
        std::clamp(static_cast<int>((box.north - bounds_.south) / cellHeight_), 0, side_ - 1);
    if (int64_t{c1 - c0 + 1} * (r1 - r0 + 1) > kWideCells) {
      wide_.push_back(index);
      continue;
    }
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) cells_[static_cast<size_t>(r) * side_ + c].push_back(index);
    }
  }
}

std::vector<uint32_t> DrapeIndex::near(const DegreesBox& box) const {
  if (side_ == 0 || !bounds_.intersects(box)) return {};
  std::vector<uint32_t> found = wide_;
  const auto cell = [](double offset, double size, int side) {
    return std::clamp(static_cast<int>(std::floor(offset / size)), 0, side - 1);
  };
  const int c0 = cell(box.west - bounds_.west, cellWidth_, side_);
  const int c1 = cell(box.east - bounds_.west, cellWidth_, side_);
  const int r0 = cell(box.south - bounds_.south, cellHeight_, side_);
  const int r1 = cell(box.north - bounds_.south, cellHeight_, side_);
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) {
      const std::vector<uint32_t>& in = cells_[static_cast<size_t>(r) * side_ + c];
      found.insert(found.end(), in.begin(), in.end());
    }
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

}  // namespace globe::overlays
