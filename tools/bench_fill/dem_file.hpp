// Reads a whole elevation raster (GTOPO30, or anything GDAL opens) into a dem::DemGrid on its
// snapped sample grid, through the project's RasterSource readers.
#pragma once

#include <filesystem>

#include "dem/dem_grid.hpp"
#include "geo/result.hpp"

namespace globe::bench_fill {

Result<dem::DemGrid> readDemGrid(const std::filesystem::path& path);

}  // namespace globe::bench_fill
