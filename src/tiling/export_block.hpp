// Exports one pyramid block as a standalone GTOPO30 .DEM/.HDR/.PRJ/.STX that GDAL opens.
#pragma once

#include <filesystem>

#include "core/result.hpp"
#include "geo/tile_id.hpp"

namespace globe::tiling {

Result<void> exportBlock(const std::filesystem::path& pyramidDir, const geo::TileId& tile,
                         const std::filesystem::path& outputStem);

}  // namespace globe::tiling
