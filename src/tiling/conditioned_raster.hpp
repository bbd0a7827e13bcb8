// A conditioned source read like the original (same path, format and grid): its samples held in
// memory, or spilled to an unlinked temporary file beside the pyramid and read a row at a time,
// so a continent of inputs does not have to fit in memory at once.
#pragma once

#include <filesystem>
#include <memory>

#include "conditioning/dem_grid.hpp"
#include "core/result.hpp"
#include "rasters/raster_source.hpp"

namespace globe::tiling {

std::unique_ptr<rasters::RasterSource> makeMemoryRaster(
    std::unique_ptr<rasters::RasterSource> original,
    std::shared_ptr<const conditioning::DemGrid> grid);

// Writes the grid's samples to an unlinked file in `directory` (gone when the process ends).
Result<std::unique_ptr<rasters::RasterSource>> makeSpilledRaster(
    std::unique_ptr<rasters::RasterSource> original, const conditioning::DemGrid& grid,
    const std::filesystem::path& directory);

}  // namespace globe::tiling
