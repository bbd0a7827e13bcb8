// Whole-raster read into a DemGrid, row by row.
#include "tools/bench_fill/dem_file.hpp"

#include <memory>

#include "io/raster_source.hpp"

namespace globe::bench_fill {

Result<dem::DemGrid> readDemGrid(const std::filesystem::path& path) {
  auto opened = io::openRasterSource(path);
  if (!opened) return Error{opened.error()};
  const io::RasterSource& source = **opened;
  const io::SampleGrid& g = source.grid();
  dem::DemGrid grid;
  grid.cols = g.cols;
  grid.rows = g.rows;
  grid.firstColumnLongitudeDegrees = g.firstColumnLongitudeDegrees;
  grid.firstRowLatitudeDegrees = g.firstRowLatitudeDegrees;
  grid.columnStepDegrees = g.columnStepDegrees;
  grid.rowStepDegrees = g.rowStepDegrees;
  grid.wrapsLongitude = g.wrapsLongitude;
  grid.samples.resize(static_cast<size_t>(g.rows * g.cols));
  for (int64_t row = 0; row < g.rows; ++row) {
    if (auto read = source.readRow(row, 0, g.cols, &grid.samples[grid.index(row, 0)]); !read) {
      return Error{read.error()};
    }
  }
  return grid;
}

}  // namespace globe::bench_fill
