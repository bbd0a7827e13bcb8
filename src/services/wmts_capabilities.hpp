// An OGC WMTS 1.0.0 GetCapabilities document: its layers (styles, formats, tile matrix set links,
// RESTful ResourceURL templates), its tile matrix sets as TileMatrixSets, and the KVP GetTile
// endpoint. Namespace prefixes are ignored (servers spell them differently).
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.hpp"
#include "formats/pyramid_manifest.hpp"
#include "services/tile_matrix.hpp"

namespace globe::services {

struct WmtsLayer {
  std::string identifier;
  std::string title;
  std::vector<std::string> formats;
  std::vector<std::string> styles;  // the default first
  std::vector<std::string> tileMatrixSets;
  std::map<std::string, std::string> tileTemplates;  // format -> RESTful template
  formats::BoundsDegrees bounds{-180, -90, 180, 90};
};

struct WmtsCapabilities {
  std::vector<WmtsLayer> layers;
  std::map<std::string, TileMatrixSet> tileMatrixSets;
  std::string kvpGetTileUrl;  // empty when the server offers no KVP GetTile
  std::string title;
};

Result<WmtsCapabilities> parseWmtsCapabilities(std::string_view xml, const std::string& name);

}  // namespace globe::services
