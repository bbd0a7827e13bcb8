#include "tiling/edge_profile.hpp"

#include <algorithm>
#include <cmath>

#include "terrain/height_block.hpp"

namespace globe::tiling {

EdgeProfile::EdgeProfile(std::vector<double> heightsMeters) : heights_(std::move(heightsMeters)) {
  integral_.assign(heights_.size(), 0.0);
  for (size_t i = 1; i < heights_.size(); ++i) {
    integral_[i] = integral_[i - 1] + (heights_[i - 1] + heights_[i]) / 2;
  }
}

double EdgeProfile::integralTo(double position) const {
  const auto last = static_cast<double>(heights_.size() - 1);
  position = std::clamp(position, 0.0, last);
  const auto i = std::min(static_cast<size_t>(position), heights_.size() - 1);
  const double t = position - static_cast<double>(i);
  if (t <= 0 || i + 1 >= heights_.size()) return integral_[i];
  const double end = heights_[i] + t * (heights_[i + 1] - heights_[i]);
  return integral_[i] + t * (heights_[i] + end) / 2;
}

double EdgeProfile::meanMeters(double position, double halfWindow) const {
  if (heights_.empty()) return 0.0;
  const auto last = static_cast<double>(heights_.size() - 1);
  const double low = std::clamp(position - halfWindow, 0.0, last);
  const double high = std::clamp(position + halfWindow, 0.0, last);
  if (high - low < 1e-3) {
    const double at = std::clamp(position, 0.0, last);
    const auto i = std::min(static_cast<size_t>(at), heights_.size() - 1);
    const double t = at - static_cast<double>(i);
    return i + 1 < heights_.size() ? heights_[i] + t * (heights_[i + 1] - heights_[i])
                                   : heights_[i];
  }
  return (integralTo(high) - integralTo(low)) / (high - low);
}

Result<EdgeProfiles> readEdgeProfiles(const rasters::RasterSource& raster) {
  const geo::SampleGrid& grid = raster.grid();
  auto heights = [](const std::vector<int16_t>& samples) {
    std::vector<double> meters(samples.size());
    std::transform(samples.begin(), samples.end(), meters.begin(),
                   [](int16_t s) { return terrain::seaFloorMeters(s); });
    return meters;
  };
  std::vector<int16_t> row(static_cast<size_t>(grid.cols));
  EdgeProfiles edges;
  for (const bool north : {true, false}) {
    if (auto read = raster.readRow(north ? 0 : grid.rows - 1, 0, grid.cols, row.data()); !read) {
      return Error{read.error()};
    }
    (north ? edges.north : edges.south) = EdgeProfile(heights(row));
  }
  // The side columns: one sample of each row each (a spilled raster reads no whole rows).
  std::vector<int16_t> west(static_cast<size_t>(grid.rows)), east(static_cast<size_t>(grid.rows));
  for (int64_t r = 0; r < grid.rows; ++r) {
    const auto i = static_cast<size_t>(r);
    if (auto read = raster.readRow(r, 0, 1, &west[i]); !read) return Error{read.error()};
    if (auto read = raster.readRow(r, grid.cols - 1, 1, &east[i]); !read) {
      return Error{read.error()};
    }
  }
  edges.west = EdgeProfile(heights(west));
  edges.east = EdgeProfile(heights(east));
  return edges;
}

}  // namespace globe::tiling
