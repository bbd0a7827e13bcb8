// The native GTOPO30 RasterSource: rows come straight from the .DEM with pread, nothing is cached.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "rasters/gtopo30.hpp"
#include "rasters/raster_source.hpp"

namespace globe::rasters {
namespace {

geo::SampleGrid nativeGrid(const Gtopo30Header& h) {
  geo::SampleGrid g;
  g.cols = h.cols;
  g.rows = h.rows;
  g.firstColumnLongitudeDegrees = h.ulxMapDegrees;
  g.firstRowLatitudeDegrees = h.ulyMapDegrees;
  g.columnStepDegrees = h.xDimDegrees;
  g.rowStepDegrees = h.yDimDegrees;
  return g;
}

class Gtopo30Source final : public detail::ColumnMappedSource {
 public:
  Gtopo30Source(Gtopo30File file, formats::VerticalUnits vertical)
      : ColumnMappedSource(file.paths().data.string(), nativeGrid(file.header()),
                           std::move(vertical)),
        file_(std::move(file)) {}

  std::string_view formatName() const override { return "GTOPO30"; }

 private:
  Result<void> readSourceColumns(int64_t row, int64_t sourceColumn, int64_t count,
                                 int16_t* out) const override {
    if (auto r = file_.readSamples(row, sourceColumn, count, out); !r) return r;
    // A header may declare another no-data value (SRTM's -32768); globe uses -9999 throughout.
    const int32_t noData = file_.header().noData;
    if (noData != kNoDataHeight && noData >= INT16_MIN && noData <= INT16_MAX) {
      for (int64_t i = 0; i < count; ++i) {
        if (out[i] == noData) out[i] = kNoDataHeight;
      }
    }
    // Only --z-units / --z-scale change GTOPO30's metres.
    if (const formats::VerticalUnits& u = verticalUnits(); !u.isIdentity()) {
      for (int64_t i = 0; i < count; ++i) {
        if (out[i] == kNoDataHeight) continue;
        out[i] =
            static_cast<int16_t>(std::clamp(std::nearbyint(u.toMeters(out[i])), -32768.0, 32767.0));
      }
    }
    return {};
  }

  Gtopo30File file_;
};

}  // namespace

Result<std::unique_ptr<RasterSource>> openGtopo30Source(const std::filesystem::path& path,
                                                        const RasterOpenOptions& options) {
  auto file = Gtopo30File::open(path);
  if (!file) return Error{file.error()};
  auto vertical =
      formats::resolveVerticalUnits(file->paths().data.string(), "m", 1, 0, options.vertical,
                                    /*formatIsMeters=*/true);
  if (!vertical) return Error{vertical.error()};
  return std::unique_ptr<RasterSource>(
      std::make_unique<Gtopo30Source>(std::move(*file), std::move(*vertical)));
}

}  // namespace globe::rasters
