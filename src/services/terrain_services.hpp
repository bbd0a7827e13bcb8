// Opens the terrain a user names, wherever a pyramid is accepted: a pack pyramid's directory or
// URL, or a standard service by prefix:
//   quantized-mesh:URL   Cesium terrain (layer.json or its folder; quantized-mesh or heightmap)
//   terrarium:TEMPLATE   Terrarium PNG tiles (AWS Terrain Tiles)
//   terrain-rgb:TEMPLATE Mapbox Terrain-RGB PNG tiles
#pragma once

#include <memory>
#include <string>

#include "core/result.hpp"
#include "streaming/terrain_source.hpp"
#include "transport/network_settings.hpp"

namespace globe::services {

// Whether `spec` names a service rather than a pyramid.
bool isTerrainService(const std::string& spec);

Result<std::unique_ptr<streaming::TerrainSource>> openTerrainSource(
    const std::string& spec, terrain::SeaSurface sea, std::shared_ptr<transport::Network> network);

}  // namespace globe::services
