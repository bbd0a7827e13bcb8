// An OSGeo TMS tilemapresource.xml (gdal2tiles', CesiumJS's Natural Earth II): its SRS, extent,
// origin, tile format and tile sets, as a TileMatrixSet with rows from the top.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/result.hpp"
#include "formats/pyramid_manifest.hpp"
#include "services/tile_matrix.hpp"

namespace globe::services {

struct TmsTileMap {
  TileMatrixSet tiling;            // matrices in the tile sets' order, rows from the top
  std::vector<std::string> hrefs;  // per matrix: the tile set's folder, relative to the XML
  std::string extension;           // "jpg", "png"
  formats::BoundsDegrees bounds;   // the bounding box, in degrees
  std::string title;
};

// Errors name `name`: not XML, not a TileMap, an SRS other than EPSG:4326 or Web Mercator, no
// tile sets, sizes out of range.
Result<TmsTileMap> parseTmsTileMap(std::string_view xml, const std::string& name);

}  // namespace globe::services
