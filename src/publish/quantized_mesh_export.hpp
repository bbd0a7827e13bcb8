// A pyramid as a Cesium terrain tileset: DIR/layer.json and DIR/{z}/{x}/{y}.terrain, gzip-
// compressed quantized-mesh-1.0 in the geographic TMS tiling (the pyramid's quadtree, rows from
// the south), every present tile of the region's levels, `available` listing what the tree
// holds. Each tile is the 65×65 grid of the pyramid's exact surface (from the level whose
// vertices those are: two deeper for 17-vertex blocks), as clients expect of the format; the
// TIN simplified to the tile's error is yet to come. What CesiumJS's CesiumTerrainProvider and
// globe's quantized-mesh: source read.
#pragma once

#include <filesystem>
#include <string>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "publish/export_writes.hpp"
#include "streaming/terrain_source.hpp"

namespace globe::publish {

Result<ExportReport> exportQuantizedMesh(streaming::TerrainSource& source,
                                         const ExportRegion& region,
                                         const std::filesystem::path& outDir,
                                         const geo::Ellipsoid& ellipsoid);

}  // namespace globe::publish
