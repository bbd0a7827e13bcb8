#include "tiles3d/drawn_surface.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace globe::tiles3d {
namespace {

// The bin range [first, last] a span covers along one axis.
std::pair<uint32_t, uint32_t> binSpan(double from, double to, double perRadian, uint32_t bins) {
  const auto clamp = [&](double v) {
    return static_cast<uint32_t>(std::clamp(v * perRadian, 0.0, static_cast<double>(bins - 1)));
  };
  return {clamp(from), clamp(to)};
}

}  // namespace

DrawnSurface::DrawnSurface(std::vector<std::shared_ptr<const LoadedContent>> contents) {
  for (auto& c : contents) {
    if (c && !c->grid.empty()) contents_.push_back(std::move(c));
  }
  if (contents_.empty()) return;
  rectangle_ = contents_[0]->grid.rectangle();
  for (const auto& c : contents_) {
    const geo::GlobeRectangle& r = c->grid.rectangle();
    rectangle_.westRadians = std::min(rectangle_.westRadians, r.westRadians);
    rectangle_.eastRadians = std::max(rectangle_.eastRadians, r.eastRadians);
    rectangle_.southRadians = std::min(rectangle_.southRadians, r.southRadians);
    rectangle_.northRadians = std::max(rectangle_.northRadians, r.northRadians);
    maximumMeters_ = std::max(maximumMeters_, c->grid.maximumHeightMeters());
  }
  // Contents on both sides of ±180° or spread over half the globe: one bin holds them all.
  const bool binned = rectangle_.widthRadians() < std::numbers::pi;
  binsX_ = binned ? kBinsPerSide : 1;
  binsY_ = binned ? kBinsPerSide : 1;
  const double w = rectangle_.widthRadians(), h = rectangle_.heightRadians();
  binsPerRadianX_ = binned && w > 0 ? binsX_ / w : 0.0;
  binsPerRadianY_ = binned && h > 0 ? binsY_ / h : 0.0;
  std::vector<std::vector<uint32_t>> bins(size_t{binsX_} * binsY_);
  for (uint32_t i = 0; i < contents_.size(); ++i) {
    const geo::GlobeRectangle& r = contents_[i]->grid.rectangle();
    const auto [x0, x1] = binSpan(r.westRadians - rectangle_.westRadians,
                                  r.eastRadians - rectangle_.westRadians, binsPerRadianX_, binsX_);
    const auto [y0, y1] =
        binSpan(r.southRadians - rectangle_.southRadians, r.northRadians - rectangle_.southRadians,
                binsPerRadianY_, binsY_);
    for (uint32_t y = y0; y <= y1; ++y) {
      for (uint32_t x = x0; x <= x1; ++x) bins[size_t{y} * binsX_ + x].push_back(i);
    }
  }
  binStart_.reserve(bins.size() + 1);
  for (const auto& bin : bins) {
    binStart_.push_back(static_cast<uint32_t>(binGrids_.size()));
    for (const uint32_t i : bin) binGrids_.push_back(&contents_[i]->grid);
  }
  binStart_.push_back(static_cast<uint32_t>(binGrids_.size()));
}

}  // namespace globe::tiles3d
