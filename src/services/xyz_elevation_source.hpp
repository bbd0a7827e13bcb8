// Web-Mercator elevation tiles encoded in PNG colours (Terrarium: the open AWS Terrain Tiles;
// Mapbox Terrain-RGB) as a terrain source: each block's vertices and apron are sampled
// bilinearly from the Mercator tiles of about the block's resolution as it loads, so the
// geographic blocks carry the service's heights without a Mercator distortion. The finest
// zoom's blocks also carry the TIN of their pixels (pixel_tin.hpp), which they are drawn and
// collided as: the pixels' bilinear surface within 0.25 m, cliffs included. The tree goes on
// past the finest zoom until its vertices are finer than the pixels north-south too (deeper
// towards the poles), so the grids where no TIN is made (the data's edge) follow them closely.
#pragma once

#include <memory>
#include <string>

#include "services/service_terrain.hpp"
#include "transport/network_settings.hpp"

namespace globe::services {

enum class ElevationEncoding { Terrarium, TerrainRgb };

// `spec`: a tile URL template ({z} {x} {y}, {-y}, {s}) with options as query keys: maxzoom
// (15 Terrarium, 14 Terrain-RGB by default), minzoom (below it nothing is asked for),
// subdomains (letters, "abc"), tilesize (256 or 512), sea (metres at or below which a sample is
// water, 0 by default: Terrain-RGB writes its sea as 0 m, Terrarium its sea floor below it;
// none: all land, for land below sea level).
Result<std::unique_ptr<ServiceTerrainSource>> openXyzElevationSource(
    ElevationEncoding encoding, const std::string& spec, terrain::SeaSurface sea,
    std::shared_ptr<transport::Network> network);

// The height a pixel encodes, NaN for a transparent pixel (no data).
double decodeElevationPixel(ElevationEncoding encoding, const uint8_t rgba[4]);

}  // namespace globe::services
