// What the Cesium terrain exporters (quantized-mesh-1.0, heightmap-1.0) share: which tiles a
// region's level holds, where a tile goes in the TMS tree, the tree's version and its layer.json
// (written last, from what the tree holds on disk, so runs over other levels or regions add up).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.hpp"
#include "formats/pyramid_manifest.hpp"
#include "geo/tile_id.hpp"
#include "publish/export_writes.hpp"
#include "streaming/terrain_source.hpp"

namespace globe::publish {

// Tiles of the level whose rectangle meets the region (degrees), inside the packs it lists.
std::vector<geo::TileId> candidateTiles(const formats::PyramidManifest& manifest, uint32_t level,
                                        const ExportRegion& region);

// The tile's row in the TMS tiling (rows from the south).
uint32_t tmsRow(const geo::TileId& tile);

// DIR/{z}/{x}/{TMS y}.terrain.
std::filesystem::path terrainTilePath(const std::filesystem::path& outDir, const geo::TileId& tile);

// The tiles' version, in their URLs ({version}): what they are made from and how, so that a
// client may keep a tile it has as long as the version is the same (tiles of a re-tiled
// pyramid, or made by another exporter or revision, get new URLs). `exporter` tells trees of
// other formats apart (quantized-mesh's is empty).
std::string treeVersion(const formats::PyramidManifest& manifest, int exporterRevision,
                        std::string_view exporter = {});

// DIR/layer.json for `format` ("quantized-mesh-1.0", "heightmap-1.0"): `available` lists the
// .terrain tiles the tree holds now (this run's and earlier runs'), `extensions` those every
// tile carries. Always rewritten.
Result<void> writeTerrainLayerJson(const std::filesystem::path& outDir, const std::string& format,
                                   const std::string& version,
                                   const streaming::TerrainSource& source,
                                   const std::vector<std::string>& extensions = {});

}  // namespace globe::publish
