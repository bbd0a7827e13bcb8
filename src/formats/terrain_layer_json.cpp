#include "formats/terrain_layer_json.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>

namespace globe::formats {
namespace {

// Levels beyond this are refused: the quadtree stops at geo::kMaxLevel.
constexpr uint32_t kMaxServiceLevel = 30;
// A TileRange's members as JSON names them, in its order.
constexpr const char* kRangeKeys[] = {"startX", "startY", "endX", "endY"};

std::string stringOr(const nlohmann::json& j, const char* key, std::string fallback) {
  auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : fallback;
}

// A whole number in 0..2^32-1 (a float only when whole, as JavaScript writes numbers). nlohmann's
// get<uint32_t> converts 5e66 to an integer with undefined behaviour (found by fuzzing).
std::optional<uint32_t> asUnsigned32(const nlohmann::json& value) {
  constexpr double kMax = std::numeric_limits<uint32_t>::max();
  if (value.is_number_unsigned()) {
    const auto v = value.get<uint64_t>();
    return v <= std::numeric_limits<uint32_t>::max() ? std::optional(static_cast<uint32_t>(v))
                                                     : std::nullopt;
  }
  if (value.is_number_float()) {
    const double d = value.get<double>();
    if (d >= 0.0 && d <= kMax && d == std::floor(d)) return static_cast<uint32_t>(d);
  }
  return std::nullopt;  // negative, fractional, out of range, not a number
}

// object[key] as asUnsigned32; `fallback` when absent (nullopt: the key is required).
Result<uint32_t> unsignedAt(const nlohmann::json& object, const char* key,
                            std::optional<uint32_t> fallback, const std::string& name) {
  const auto it = object.is_object() ? object.find(key) : object.end();
  if (!object.is_object() || it == object.end()) {
    if (fallback) return *fallback;
    return makeError(name + ": \"" + key + "\" missing");
  }
  if (const auto v = asUnsigned32(*it)) return *v;
  return makeError(name + ": \"" + key + "\" is not a whole number in 0..4294967295 (" +
                   it->dump().substr(0, 40) + ")");
}

}  // namespace

std::optional<TileRange> tileRangeFromJson(const nlohmann::json& range) {
  uint32_t bounds[4];
  for (const int k : {0, 1, 2, 3}) {
    auto v = unsignedAt(range, kRangeKeys[k], std::nullopt, "");
    if (!v) return std::nullopt;
    bounds[k] = *v;
  }
  return TileRange{bounds[0], bounds[1], bounds[2], bounds[3]};
}

bool TerrainLayerJson::hasExtension(std::string_view name) const {
  return std::find(extensions.begin(), extensions.end(), name) != extensions.end();
}

Result<TerrainLayerJson> parseTerrainLayerJson(std::string_view text, const std::string& name) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    return makeError(name + ": not JSON (" + e.what() + ")");
  }
  if (!j.is_object()) return makeError(name + ": not a layer.json (no JSON object)");
  TerrainLayerJson layer;
  try {
    const std::string format = stringOr(j, "format", "heightmap-1.0");
    // Any 1.x quantized mesh, as CesiumJS reads it: the minor versions add extensions only.
    if (format.starts_with("quantized-mesh-1.")) {
      layer.format = TerrainLayerJson::Format::QuantizedMesh;
    } else if (format == "heightmap-1.0") {
      layer.format = TerrainLayerJson::Format::Heightmap;
    } else {
      return makeError(name + ": format \"" + format +
                       "\" (quantized-mesh-1.x or heightmap-1.0 expected)");
    }
    const std::string projection = stringOr(j, "projection", "EPSG:4326");
    if (projection != "EPSG:4326") {
      return makeError(name + ": projection " + projection +
                       " (only EPSG:4326, Cesium's geographic tiling, is this viewer's quadtree)");
    }
    const std::string scheme = stringOr(j, "scheme", stringOr(j, "schema", "tms"));
    if (scheme != "tms") return makeError(name + ": scheme \"" + scheme + "\" (tms expected)");
    layer.version = stringOr(j, "version", "1.0.0");
    layer.attribution = stringOr(j, "attribution", "");
    if (auto t = j.find("tiles"); t != j.end() && t->is_array()) {
      for (const auto& s : *t)
        if (s.is_string()) layer.tiles.push_back(s.get<std::string>());
    }
    if (layer.tiles.empty()) return makeError(name + ": no tile URL template (\"tiles\")");
    if (auto e = j.find("extensions"); e != j.end() && e->is_array()) {
      for (const auto& s : *e)
        if (s.is_string()) layer.extensions.push_back(s.get<std::string>());
    }
    auto metadata = unsignedAt(j, "metadataAvailability", 0u, name);
    auto minZoom = unsignedAt(j, "minzoom", 0u, name);
    auto maxZoom = unsignedAt(j, "maxzoom", 0u, name);
    for (const auto* field : {&metadata, &minZoom, &maxZoom}) {
      if (!*field) return Error{field->error()};
    }
    layer.metadataAvailability = *metadata;
    layer.minZoom = *minZoom;
    layer.maxZoom = *maxZoom;
    if (auto a = j.find("available"); a != j.end() && a->is_array()) {
      if (a->size() > kMaxServiceLevel + 1) {
        return makeError(name + ": \"available\" lists " + std::to_string(a->size()) +
                         " levels (at most " + std::to_string(kMaxServiceLevel + 1) + ")");
      }
      for (const auto& level : *a) {
        std::vector<TileRange> ranges;
        const uint32_t z = static_cast<uint32_t>(layer.available.size());
        const uint64_t columns = uint64_t{2} << z, rows = uint64_t{1} << z;
        for (const auto& r : level) {
          uint32_t bounds[4];
          for (const int k : {0, 1, 2, 3}) {
            auto v = unsignedAt(r, kRangeKeys[k], std::nullopt,
                                name + ": level " + std::to_string(layer.available.size()));
            if (!v) return Error{v.error()};
            bounds[k] = *v;
          }
          TileRange range{bounds[0], bounds[1], bounds[2], bounds[3]};
          if (range.startX > range.endX || range.startY > range.endY || range.endX >= columns ||
              range.endY >= rows) {
            return makeError(name + ": level " + std::to_string(z) +
                             " lists tiles outside the level's " + std::to_string(columns) + "×" +
                             std::to_string(rows) + " grid");
          }
          ranges.push_back(range);
        }
        layer.available.push_back(std::move(ranges));
      }
      // Trailing empty levels say nothing is there.
      while (!layer.available.empty() && layer.available.back().empty()) layer.available.pop_back();
      // Beyond what it lists, only tiles' metadata can say what exists (metadataAvailability):
      // then its maxzoom bounds the levels, else the last level listed does.
      if (!layer.available.empty()) {
        const auto listed = static_cast<uint32_t>(layer.available.size() - 1);
        layer.maxZoom = layer.metadataAvailability > 0 ? std::max(layer.maxZoom, listed) : listed;
      }
    }
    if (layer.maxZoom > kMaxServiceLevel) {
      return makeError(name + ": maxzoom " + std::to_string(layer.maxZoom) + " (at most " +
                       std::to_string(kMaxServiceLevel) + ")");
    }
  } catch (const nlohmann::json::exception& e) {
    return makeError(name + ": a malformed layer.json (" + e.what() + ")");
  }
  return layer;
}

}  // namespace globe::formats
