// RasterSource: the streaming, thread-safe row reader the tiler samples heights from (GTOPO30 or
// anything GDAL opens), with its sample grid in geographic degrees.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include "core/result.hpp"
#include "formats/vertical_units.hpp"
#include "geo/sample_grid.hpp"

namespace globe::rasters {

class RasterSource {
 public:
  virtual ~RasterSource() = default;
  virtual const std::string& path() const = 0;
  virtual std::string_view formatName() const = 0;  // "GTOPO30" or the GDAL driver short name
  virtual const geo::SampleGrid& grid() const = 0;
  // Reads `count` samples of row `row` from column `firstColumn` into out as GTOPO30 heights:
  // int16 metres, rounded to nearest (ties to even); the source's no-data value, NaN and
  // infinities become -9999; finite values outside int16 are clamped. Columns may lie outside
  // [0, cols) only when the grid wraps (they wrap, any number of times). Thread-safe.
  virtual Result<void> readRow(int64_t row, int64_t firstColumn, int64_t count,
                               int16_t* out) const = 0;
  // How readRow turned the stored values into metres (metres as stored unless a reader says).
  virtual const formats::VerticalUnits& verticalUnits() const;
};

struct RasterOpenOptions {
  formats::VerticalOverride vertical;  // unset: each file's own unit type, scale and offset
  // A picture (8-bit red/green/blue bands, or a palette) is refused as elevation unless this is
  // set (globe-tiler --force): its band 1 would be tiled as heights in metres.
  bool allowImages = false;
};

// Native GTOPO30 reader: pread per row, never loads the file.
// Heights are metres by the format; an override still applies.
Result<std::unique_ptr<RasterSource>> openGtopo30Source(const std::filesystem::path& path,
                                                        const RasterOpenOptions& options = {});
// Any raster GDAL opens, band 1; projected rasters are warped (bilinear) to WGS84 degrees. The
// band's unit type, scale and offset make metres (an unknown unit is an error).
Result<std::unique_ptr<RasterSource>> openGdalSource(const std::filesystem::path& path,
                                                     const RasterOpenOptions& options = {});
// The native reader for GTOPO30 (.DEM/.BIL/.HDR with a GTOPO30 .HDR), otherwise GDAL.
Result<std::unique_ptr<RasterSource>> openRasterSource(const std::filesystem::path& path,
                                                       const RasterOpenOptions& options = {});

// If 1/step is within 1e-4 (relative) of an integer n, step := 1/n (unless that moves the last
// sample by more than 5% of a step); then a first centre within 1e-3 of a step of a multiple of
// 1/(2n) becomes exactly k/(2n). Both axes; other values are left alone. wrapsLongitude is
// recomputed from the snapped values.
geo::SampleGrid snapSampleGrid(geo::SampleGrid grid);

namespace detail {

// Which source column a published grid column reads: (column + offset) mod period, where period
// is the number of source columns in one turn for wrapping grids, cols otherwise.
struct ColumnMap {
  int64_t offset = 0;
  int64_t period = 0;
};

// The grid a source publishes given its own: snapped; a wrapping grid is cut to exactly one turn
// (dropping repeated columns such as netCDF's 1081st) and rotated so that column 0 is the first
// cell whose west edge is at or east of -180. A wrapping grid whose step does not divide 360 is
// published as not wrapping.
struct PublishedGrid {
  geo::SampleGrid grid;
  ColumnMap columns;
};
PublishedGrid publishGrid(const geo::SampleGrid& native);

// Implements readRow's argument checks and wrapping on top of contiguous reads of source columns.
class ColumnMappedSource : public RasterSource {
 public:
  const std::string& path() const override { return path_; }
  const geo::SampleGrid& grid() const override { return published_.grid; }
  Result<void> readRow(int64_t row, int64_t firstColumn, int64_t count, int16_t* out) const final;
  const formats::VerticalUnits& verticalUnits() const override { return vertical_; }

 protected:
  ColumnMappedSource(std::string path, const geo::SampleGrid& nativeGrid,
                     formats::VerticalUnits vertical = {})
      : path_(std::move(path)),
        published_(publishGrid(nativeGrid)),
        vertical_(std::move(vertical)) {}
  // Reads source columns [sourceColumn, sourceColumn + count) of grid row `row`, all in range.
  virtual Result<void> readSourceColumns(int64_t row, int64_t sourceColumn, int64_t count,
                                         int16_t* out) const = 0;

 private:
  std::string path_;
  PublishedGrid published_;
  formats::VerticalUnits vertical_;
};

}  // namespace detail
}  // namespace globe::rasters
