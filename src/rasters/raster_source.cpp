// Sample-grid snapping and publishing, wrapped row reads, and choosing a reader for a file.
#include "rasters/raster_source.hpp"

#include <algorithm>
#include <cmath>

#include "core/ascii_case.hpp"
#include "rasters/gtopo30.hpp"
#include "transport/atomic_file.hpp"

namespace globe::rasters {
namespace {

// Snaps one axis of `count` samples (see snapSampleGrid).
void snapAxis(double& step, double& first, int64_t count) {
  if (!std::isfinite(step) || !(step > 0) || !std::isfinite(first)) return;
  const double inverse = 1.0 / step;
  const double n = std::round(inverse);
  if (!std::isfinite(inverse) || n < 1 || n > 1e12 || std::abs(inverse - n) > 1e-4 * n) return;
  // For fine steps 1e-4 of n is a wide net (every step finer than 1/5000 degree is caught): also
  // refuse when the new step would move the far end of the grid by more than 5% of a cell.
  if (static_cast<double>(std::max<int64_t>(count, 0)) * std::abs(step - 1.0 / n) > 0.05 * step) {
    return;
  }
  step = 1.0 / n;
  const double k = std::round(first * 2 * n);
  // k / (2n) rather than k * (step / 2): one rounding, so -1079/6 comes out as the nearest double.
  if (std::abs(first - k / (2 * n)) <= 1e-3 * step) first = k / (2 * n);
}

bool coversEveryLongitude(const geo::SampleGrid& g) {
  return static_cast<double>(g.cols) * g.columnStepDegrees >= 360.0 - 1e-3 * g.columnStepDegrees;
}

}  // namespace

const formats::VerticalUnits& RasterSource::verticalUnits() const {
  static const formats::VerticalUnits kMeters;
  return kMeters;
}

geo::SampleGrid snapSampleGrid(geo::SampleGrid grid) {
  snapAxis(grid.columnStepDegrees, grid.firstColumnLongitudeDegrees, grid.cols);
  snapAxis(grid.rowStepDegrees, grid.firstRowLatitudeDegrees, grid.rows);
  grid.wrapsLongitude = coversEveryLongitude(grid);
  return grid;
}

namespace detail {

PublishedGrid publishGrid(const geo::SampleGrid& native) {
  geo::SampleGrid g = snapSampleGrid(native);
  const double step = g.columnStepDegrees;
  const double turn = 360.0 / step;
  const double period = std::round(turn);
  if (g.wrapsLongitude && std::abs(turn - period) > 1e-6 * period) g.wrapsLongitude = false;

  if (!g.wrapsLongitude) {
    // Whole turns only, and only when the grid lies entirely outside [-180, 180).
    const double west = g.westDegrees(), east = g.eastDegrees();
    if (std::isfinite(west) && std::isfinite(east) && (west >= 180.0 || east <= -180.0)) {
      g.firstColumnLongitudeDegrees -= 360.0 * std::floor((west + 180.0) / 360.0);
      g = snapSampleGrid(g);
    }
    return {g, {0, g.cols}};
  }

  // Measured in steps: source column j starts at w + j; the published grid starts at t + [0, 1).
  const auto periodColumns = static_cast<int64_t>(period);
  const double w = (g.firstColumnLongitudeDegrees - step / 2) / step;
  const double t = -180.0 / step;
  const auto shift = static_cast<int64_t>(std::ceil(t - w - 1e-6));
  const int64_t offset = ((shift % periodColumns) + periodColumns) % periodColumns;
  double first = g.firstColumnLongitudeDegrees + static_cast<double>(offset) * step;
  first -= 360.0 * std::floor((first - step / 2 + 180.0 + 1e-6 * step) / 360.0);
  g.firstColumnLongitudeDegrees = first;
  g.cols = periodColumns;
  g = snapSampleGrid(g);  // restores k/(2n) exactness lost in the additions
  return {g, {offset, periodColumns}};
}

Result<void> ColumnMappedSource::readRow(int64_t row, int64_t firstColumn, int64_t count,
                                         int16_t* out) const {
  const geo::SampleGrid& g = published_.grid;
  const ColumnMap& map = published_.columns;
  auto outside = [&](const std::string& what) -> Result<void> {
    return makeError(path_ + ": cannot read " + what + " of a " + std::to_string(g.rows) + " x " +
                     std::to_string(g.cols) + " raster");
  };
  if (map.period <= 0) return outside("anything");
  if (row < 0 || row >= g.rows) return outside("row " + std::to_string(row));
  if (count < 0) return outside(std::to_string(count) + " columns");
  const std::string columns = "columns " + std::to_string(firstColumn) + " + " +
                              std::to_string(count) + " of row " + std::to_string(row);
  if (!g.wrapsLongitude &&
      (firstColumn < 0 || firstColumn > g.cols || count > g.cols - firstColumn)) {
    return outside(columns);
  }
  int64_t column = ((firstColumn % map.period) + map.period) % map.period;
  while (count > 0) {
    const int64_t source = (column + map.offset) % map.period;
    const int64_t n = std::min(count, map.period - source);
    if (auto r = readSourceColumns(row, source, n, out); !r) return r;
    out += n;
    count -= n;
    column = (column + n) % map.period;
  }
  return {};
}

}  // namespace detail

Result<std::unique_ptr<RasterSource>> openRasterSource(const std::filesystem::path& path,
                                                       const RasterOpenOptions& options) {
  std::error_code ec;
  // GDAL's virtual file systems (/vsicurl/ for HTTP range reads, /vsis3/, /vsizip/, ...): GDAL's.
  if (path.string().starts_with("/vsi")) return openGdalSource(path, options);
  // A directory: e.g. an Arc/Info grid.
  if (std::filesystem::is_directory(path, ec)) return openGdalSource(path, options);
  const std::string ext = core::asciiLower(path.extension().string());
  const bool exists = std::filesystem::exists(path, ec);
  const bool gtopoName = ext == ".dem" || ext == ".bil" || ext == ".hdr";
  if (exists && !gtopoName) return openGdalSource(path, options);

  auto files = findGtopo30Files(path);
  if (files) {
    // ENVI also writes .hdr files, in a different format that GDAL reads.
    auto text = transport::readWholeFile(files->header, 1 << 20);
    if (text && text->size() >= 4 &&
        core::asciiLower(std::string_view(reinterpret_cast<const char*>(text->data()), 4)) ==
            "envi") {
      return openGdalSource(files->data, options);
    }
    return openGtopo30Source(path, options);
  }
  if (exists && ext != ".hdr") {
    // A .dem without .HDR is probably another format (USGS DEM); say why GTOPO30 was not used.
    auto gdal = openGdalSource(path, options);
    if (gdal) return gdal;
    return makeError(gdal.error() + "; and as GTOPO30: " + files.error());
  }
  if (!exists && !gtopoName && !ext.empty()) return makeError(path.string() + ": no such file");
  return Error{files.error()};
}

}  // namespace globe::rasters
