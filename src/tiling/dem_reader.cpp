#include "tiling/dem_reader.hpp"

#include <string>

namespace globe::tiling {

Result<conditioning::DemGrid> readDemGrid(const rasters::RasterSource& source,
                                          const std::string& name) {
  const geo::SampleGrid& g = source.grid();
  const auto samples = static_cast<uint64_t>(g.cols) * static_cast<uint64_t>(g.rows);
  if (samples > kMaxDemGridSamples) {
    return makeError(name + ": " + std::to_string(samples) + " samples is more than the " +
                     std::to_string(kMaxDemGridSamples) +
                     " one input may have (each input is conditioned in memory); split it into "
                     "tiles (e.g. gdal_retile.py) and give them all");
  }
  conditioning::DemGrid grid;
  static_cast<geo::SampleGrid&>(grid) = g;
  grid.samples.resize(static_cast<size_t>(samples));
  for (int64_t row = 0; row < g.rows; ++row) {
    if (auto read = source.readRow(row, 0, g.cols, grid.samples.data() + grid.index(row, 0));
        !read) {
      return Error{read.error()};
    }
  }
  return grid;
}

Result<conditioning::DemGrid> readDemGrid(const std::filesystem::path& path) {
  auto opened = rasters::openRasterSource(path);
  if (!opened) return Error{opened.error()};
  return readDemGrid(**opened, path.string());
}

}  // namespace globe::tiling
