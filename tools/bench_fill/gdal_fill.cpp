// GDALFillNodata through the C API on a MEM dataset.
#include "tools/bench_fill/gdal_fill.hpp"

#include <gdal.h>
#include <gdal_alg.h>

#include <cpl_string.h>
#include <chrono>
#include <memory>
#include <mutex>

#include "rasters/gtopo30_header.hpp"

namespace globe::bench_fill {
namespace {

struct DatasetCloser {
  void operator()(void* dataset) const { GDALClose(dataset); }
};
using DatasetPtr = std::unique_ptr<void, DatasetCloser>;

struct OptionsFree {
  void operator()(char** list) const { CSLDestroy(list); }
};

std::string lastGdalError(const std::string& what) { return what + ": " + CPLGetLastErrorMsg(); }

}  // namespace

Result<GdalFillResult> gdalFillNodata(const conditioning::DemGrid& grid,
                                      const std::vector<uint8_t>& isVoid,
                                      const GdalFillOptions& options) {
  static std::once_flag registered;
  std::call_once(registered, [] { GDALAllRegister(); });
  GDALDriverH mem = GDALGetDriverByName("MEM");
  if (!mem) return Error{"GDAL has no MEM driver"};
  const auto cols = static_cast<int>(grid.cols), rows = static_cast<int>(grid.rows);
  DatasetPtr dataset(GDALCreate(mem, "", cols, rows, 1, GDT_Int16, nullptr));
  if (!dataset) return Error{lastGdalError("GDALCreate(MEM)")};
  GDALRasterBandH band = GDALGetRasterBand(dataset.get(), 1);
  GDALSetRasterNoDataValue(band, rasters::kNoDataHeight);

  GdalFillResult result;
  result.samples = grid.samples;
  for (size_t i = 0; i < isVoid.size(); ++i) {
    if (isVoid[i]) result.samples[i] = rasters::kNoDataHeight;
  }
  if (GDALRasterIO(band, GF_Write, 0, 0, cols, rows, result.samples.data(), cols, rows, GDT_Int16,
                   0, 0) != CE_None) {
    return Error{lastGdalError("GDALRasterIO write")};
  }
  std::unique_ptr<char*, OptionsFree> fillOptions(
      CSLSetNameValue(nullptr, "TEMP_FILE_DRIVER", "MEM"));
  const auto start = std::chrono::steady_clock::now();
  const CPLErr filled =
      GDALFillNodata(band, nullptr, options.maxSearchDistancePixels, 0, options.smoothingIterations,
                     fillOptions.get(), nullptr, nullptr);
  result.fillSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (filled != CE_None) return Error{lastGdalError("GDALFillNodata")};
  if (GDALRasterIO(band, GF_Read, 0, 0, cols, rows, result.samples.data(), cols, rows, GDT_Int16, 0,
                   0) != CE_None) {
    return Error{lastGdalError("GDALRasterIO read")};
  }
  return result;
}

std::string gdalVersion() { return std::string("GDAL ") + GDALVersionInfo("RELEASE_NAME"); }

}  // namespace globe::bench_fill
