// A pyramid as a Cesium heightmap-1.0 terrain tileset: DIR/layer.json and DIR/{z}/{x}/{y}.terrain,
// gzip-compressed, in the geographic TMS tiling (the pyramid's quadtree, rows from the south).
// Each tile holds the 65×65 grid of the pyramid's exact surface (from the level whose vertices
// those are: two deeper for 17-vertex blocks) in 0.2 m steps, the mask of its children in the
// tree and a water mask (the nearest pyramid vertex's water flag, 256×256, or one byte where the
// tile is all land or all water). What CesiumJS's CesiumTerrainProvider and globe's
// quantized-mesh: source read.
#pragma once

#include <filesystem>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "publish/export_writes.hpp"
#include "streaming/terrain_source.hpp"

namespace globe::publish {

Result<ExportReport> exportHeightmap(streaming::TerrainSource& source, const ExportRegion& region,
                                     const std::filesystem::path& outDir,
                                     const geo::Ellipsoid& ellipsoid,
                                     const ExportWork& work = {});

}  // namespace globe::publish
