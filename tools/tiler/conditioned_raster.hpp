// A conditioned source read like the original (same path, format and grid): its samples held in
// memory, or spilled to an unlinked temporary file beside the pyramid and read a row at a time,
// so a continent of inputs does not have to fit in memory at once.
#pragma once

#include <filesystem>
#include <memory>

#include "dem/dem_grid.hpp"
#include "geo/result.hpp"
#include "io/raster_source.hpp"

namespace globe::tiler {

std::unique_ptr<io::RasterSource> makeMemoryRaster(std::unique_ptr<io::RasterSource> original,
                                                   std::shared_ptr<const dem::DemGrid> grid);

// Writes the grid's samples to an unlinked file in `directory` (gone when the process ends).
Result<std::unique_ptr<io::RasterSource>> makeSpilledRaster(
    std::unique_ptr<io::RasterSource> original, const dem::DemGrid& grid,
    const std::filesystem::path& directory);

}  // namespace globe::tiler
