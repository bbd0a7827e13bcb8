// A pyramid as a Cesium terrain tileset: DIR/layer.json and DIR/{z}/{x}/{y}.terrain, gzip-
// compressed quantized-mesh-1.0 in the geographic TMS tiling (the pyramid's quadtree, rows from
// the south), every present tile of the region's levels, `available` listing what the tree
// holds. Each tile is a TIN of the 65×65 grid of the pyramid's exact surface (from the level
// whose vertices those are: two deeper for 17-vertex blocks) within errorFraction × the tile's
// geometric error as CesiumJS estimates it (what it refines by), sharing its vertices on each
// side with the neighbour there (0: the whole grid, globe's surface exactly). With the extensions
// octvertexnormals (from the full grid), watermask (the sea classification) and metadata (the
// children held). What CesiumJS's CesiumTerrainProvider and globe's quantized-mesh: source read.
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
                                         const geo::Ellipsoid& ellipsoid,
                                         double errorFraction = 1.0,
                                         const ExportWork& work = {});

}  // namespace globe::publish
