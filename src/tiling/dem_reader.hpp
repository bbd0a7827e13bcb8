// Reads a whole elevation raster (GTOPO30, or anything GDAL opens) into a dem::DemGrid on its
// snapped sample grid, through the project's RasterSource readers: how the tiler's conditioning,
// the fill benchmark and the tests all get a source into memory.
#pragma once

#include <cstdint>
#include <filesystem>

#include "conditioning/dem_grid.hpp"
#include "core/result.hpp"
#include "rasters/raster_source.hpp"

namespace globe::tiling {

// About 8 GiB at the conditioning's ~8 bytes a sample: a 43200×21600 world in one file fits.
inline constexpr uint64_t kMaxDemGridSamples = uint64_t{1} << 30;

// `name` names the source in errors (the path as the user gave it).
Result<conditioning::DemGrid> readDemGrid(const rasters::RasterSource& source,
                                          const std::string& name);
Result<conditioning::DemGrid> readDemGrid(const std::filesystem::path& path);

}  // namespace globe::tiling
