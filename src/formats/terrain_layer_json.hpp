// layer.json of a Cesium terrain service (quantized-mesh-1.0 or heightmap-1.0): where its tiles
// are, which exist, and what they carry.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/result.hpp"

namespace globe::formats {

// A rectangle of TMS tile columns and rows (rows from the south), inclusive.
struct TileRange {
  uint32_t startX = 0, startY = 0, endX = 0, endY = 0;
};

struct TerrainLayerJson {
  enum class Format { QuantizedMesh, Heightmap };
  Format format = Format::QuantizedMesh;
  std::vector<std::string> tiles;  // URL templates relative to layer.json: {z} {x} {y} {version}
  std::string version;
  std::string attribution;
  std::vector<std::string> extensions;
  uint32_t minZoom = 0;
  // The deepest level `available` lists; maxzoom when it lists none, or when tiles' metadata
  // lists more (metadataAvailability).
  uint32_t maxZoom = 0;
  // available[level]: the tiles present at that level; empty means every tile to maxZoom.
  std::vector<std::vector<TileRange>> available;
  // Levels at which tiles' metadata extension lists their descendants' availability (0: none).
  uint32_t metadataAvailability = 0;
  bool hasExtension(std::string_view name) const;
};

// Parses a layer.json; errors name `name`. Refused: a projection other than EPSG:4326 (this
// viewer's quadtree is the geodetic TMS), a scheme other than tms, no tile template.
Result<TerrainLayerJson> parseTerrainLayerJson(std::string_view text, const std::string& name);

// {"startX", "startY", "endX", "endY"} (layer.json's "available", a tile's metadata extension) as
// a TileRange; nullopt where a field is missing or not a whole number in 0..2^32-1.
std::optional<TileRange> tileRangeFromJson(const nlohmann::json& range);

}  // namespace globe::formats
