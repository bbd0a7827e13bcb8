// Reading the source rasters and sampling the finest one bilinearly.
#include "tools/bench/source_reference.hpp"

#include <algorithm>
#include <cmath>

#include "io/gtopo30.hpp"

namespace globe::bench {

Result<SourceReference> SourceReference::load(const std::vector<std::filesystem::path>& rasters) {
  SourceReference reference;
  for (const std::filesystem::path& path : rasters) {
    auto raster = io::readGtopo30(path);
    if (!raster) return Error{raster.error()};
    const io::Gtopo30Header& h = raster->header;
    io::SampleGrid grid;
    grid.cols = h.cols;
    grid.rows = h.rows;
    grid.firstColumnLongitudeDegrees = h.ulxMapDegrees;
    grid.firstRowLatitudeDegrees = h.ulyMapDegrees;
    grid.columnStepDegrees = h.xDimDegrees;
    grid.rowStepDegrees = h.yDimDegrees;
    Raster r;
    r.path = path.string();
    r.grid = io::snapSampleGrid(grid);
    r.samples = std::move(raster->heights);
    for (int16_t& s : r.samples) {
      if (s == h.noData) s = io::kNoDataHeight;
    }
    r.step = std::min(r.grid.columnStepDegrees, r.grid.rowStepDegrees);
    reference.rasters_.push_back(std::move(r));
  }
  std::stable_sort(reference.rasters_.begin(), reference.rasters_.end(),
                   [](const Raster& a, const Raster& b) { return a.step < b.step; });
  return reference;
}

int16_t SourceReference::Raster::sample(int64_t row, int64_t column) const {
  if (grid.wrapsLongitude) column = ((column % grid.cols) + grid.cols) % grid.cols;
  return samples[static_cast<size_t>(row * grid.cols + column)];
}

std::optional<double> SourceReference::heightMeters(double lon, double lat) const {
  for (const Raster& r : rasters_) {
    const io::SampleGrid& g = r.grid;
    const double south = std::max(-90.0, g.southDegrees());
    const double north = std::min(90.0, g.northDegrees());
    if (lat < south || lat > north) continue;
    if (!g.wrapsLongitude && (lon < g.westDegrees() || lon > g.eastDegrees())) continue;
    double offset = lon - g.firstColumnLongitudeDegrees;
    if (g.wrapsLongitude) offset -= 360.0 * std::floor(offset / 360.0);
    double u = offset / g.columnStepDegrees;
    if (!g.wrapsLongitude) u = std::clamp(u, 0.0, static_cast<double>(g.cols - 1));
    const double v = std::clamp((g.firstRowLatitudeDegrees - lat) / g.rowStepDegrees, 0.0,
                                static_cast<double>(g.rows - 1));
    const auto c0 = static_cast<int64_t>(std::floor(u));
    const auto r0 = static_cast<int64_t>(std::floor(v));
    const int64_t c1 = g.wrapsLongitude ? c0 + 1 : std::min(c0 + 1, g.cols - 1);
    const int64_t r1 = std::min(r0 + 1, g.rows - 1);
    const double tu = u - static_cast<double>(c0), tv = v - static_cast<double>(r0);
    if (r.sample(tv < 0.5 ? r0 : r1, tu < 0.5 ? c0 : c1) == io::kNoDataHeight) return 0.0;
    auto h = [&](int64_t row, int64_t column) {
      const int16_t s = r.sample(row, column);
      return s == io::kNoDataHeight ? 0.0 : static_cast<double>(s);
    };
    return (1 - tv) * ((1 - tu) * h(r0, c0) + tu * h(r0, c1)) +
           tv * ((1 - tu) * h(r1, c0) + tu * h(r1, c1));
  }
  return std::nullopt;
}

}  // namespace globe::bench
