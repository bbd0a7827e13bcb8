// The GDAL baseline: GDALFillNodata (what gdal_fillnodata.py runs) on an in-memory copy of a grid.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "conditioning/dem_grid.hpp"
#include "core/result.hpp"

namespace globe::bench_fill {

struct GdalFillOptions {
  double maxSearchDistancePixels = 1000;
  int smoothingIterations = 0;  // gdal_fillnodata.py's default
};

struct GdalFillResult {
  std::vector<int16_t> samples;  // the band after the fill, same layout as the grid
  double fillSeconds = 0;        // GDALFillNodata alone (not the copies in and out)
};

// Copies the grid into a MEM dataset with one Int16 band whose no-data value is -9999, sets the
// void samples to -9999 and runs GDALFillNodata with the band's own mask (every no-data sample
// is filled; only valid samples feed the fill) and TEMP_FILE_DRIVER=MEM.
Result<GdalFillResult> gdalFillNodata(const conditioning::DemGrid& grid,
                                      const std::vector<uint8_t>& isVoid,
                                      const GdalFillOptions& options);

// "GDAL 3.6.2", from GDALVersionInfo.
std::string gdalVersion();

}  // namespace globe::bench_fill
