// Reading the source rasters through GDAL and sampling the finest one bilinearly.
#include "tools/bench/source_reference.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <gdal.h>

#include "rasters/gtopo30_header.hpp"

namespace globe::bench {

Result<SourceReference> SourceReference::load(const std::vector<std::filesystem::path>& rasters) {
  // Through GDAL (its EHdr driver for GTOPO30's .DEM + .HDR), not the project's own reader, so
  // that reference (b) is independent of it.
  GDALAllRegister();
  SourceReference reference;
  for (const std::filesystem::path& path : rasters) {
    const std::unique_ptr<void, decltype(&GDALClose)> dataset(GDALOpen(path.c_str(), GA_ReadOnly),
                                                              &GDALClose);
    if (!dataset) return makeError(path.string() + ": GDAL cannot open it");
    double transform[6] = {};
    if (GDALGetGeoTransform(dataset.get(), transform) != CE_None || transform[2] != 0.0 ||
        transform[4] != 0.0 || !(transform[1] > 0.0) || !(transform[5] < 0.0)) {
      return makeError(path.string() + ": no north-up geotransform");
    }
    GDALRasterBandH band = GDALGetRasterBand(dataset.get(), 1);
    if (band == nullptr) return makeError(path.string() + ": no band 1");
    geo::SampleGrid grid;
    grid.cols = GDALGetRasterXSize(dataset.get());
    grid.rows = GDALGetRasterYSize(dataset.get());
    grid.columnStepDegrees = transform[1];
    grid.rowStepDegrees = -transform[5];
    grid.firstColumnLongitudeDegrees = transform[0] + 0.5 * transform[1];  // corner -> centre
    grid.firstRowLatitudeDegrees = transform[3] + 0.5 * transform[5];
    Raster r;
    r.path = path.string();
    r.grid = rasters::snapSampleGrid(grid);
    r.samples.resize(static_cast<size_t>(grid.cols * grid.rows));
    if (GDALRasterIO(band, GF_Read, 0, 0, static_cast<int>(grid.cols), static_cast<int>(grid.rows),
                     r.samples.data(), static_cast<int>(grid.cols), static_cast<int>(grid.rows),
                     GDT_Int16, 0, 0) != CE_None) {
      return makeError(path.string() + ": GDAL cannot read band 1");
    }
    int hasNoData = 0;
    const double noData = GDALGetRasterNoDataValue(band, &hasNoData);
    for (int16_t& sample : r.samples) {
      if (hasNoData && sample == noData) sample = rasters::kNoDataHeight;
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
    const geo::SampleGrid& g = r.grid;
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
    if (r.sample(tv < 0.5 ? r0 : r1, tu < 0.5 ? c0 : c1) == rasters::kNoDataHeight) return 0.0;
    auto h = [&](int64_t row, int64_t column) {
      const int16_t s = r.sample(row, column);
      return s == rasters::kNoDataHeight ? 0.0 : static_cast<double>(s);
    };
    return (1 - tv) * ((1 - tu) * h(r0, c0) + tu * h(r0, c1)) +
           tv * ((1 - tu) * h(r1, c0) + tu * h(r1, c1));
  }
  return std::nullopt;
}

}  // namespace globe::bench
