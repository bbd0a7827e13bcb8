// A Cesium terrain service (quantized-mesh-1.0 or heightmap-1.0 tiles, layer.json) as a terrain
// source: its geographic TMS tiling is this viewer's quadtree, so each tile is one block, its
// TIN sampled at the block's vertices.
#pragma once

#include <memory>
#include <string>

#include "services/service_terrain.hpp"
#include "transport/network_settings.hpp"

namespace globe::services {

// `url`: layer.json's URL, or its folder's. Errors: no layer.json there, or one this viewer
// cannot use (formats/terrain_layer_json.hpp), naming the URL.
Result<std::unique_ptr<ServiceTerrainSource>> openQuantizedMeshSource(
    const std::string& url, terrain::SeaSurface sea, std::shared_ptr<transport::Network> network);

}  // namespace globe::services
