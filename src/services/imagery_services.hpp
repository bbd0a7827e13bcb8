// Opens the imagery layer a user names, wherever --layer is: a layer of image packs made by
// globe-tiler (a directory or its URL), or a standard service by prefix:
//   xyz:TEMPLATE     {z}/{x}/{y} tiles ({-y} TMS rows, {s} subdomains); Web Mercator, or
//                    ?crs=EPSG:4326 for the geographic tiling with two tiles at zoom 0; options
//                    minzoom, maxzoom, subdomains, tilesize, attribution
//   tms:URL          an OSGeo TMS tilemapresource.xml, or its folder
//   wmts:URL?layer=NAME[&tilematrixset=ID&style=S&time=T]   a WMTS GetCapabilities document (KVP or
//                    RESTful)
//   pmtiles:URL      a PMTiles v3 archive of PNG, JPEG, WebP or AVIF tiles, read by range
#pragma once

#include <memory>
#include <string>

#include "core/result.hpp"
#include "streaming/imagery_tiles.hpp"
#include "transport/network_settings.hpp"

namespace globe::services {

bool isImageryService(const std::string& spec);

Result<std::unique_ptr<streaming::ImageryTiles>> openImageryTiles(
    const std::string& spec, std::shared_ptr<transport::Network> network);

}  // namespace globe::services
