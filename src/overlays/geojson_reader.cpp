#include "overlays/geojson_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "overlays/overlay_budget.hpp"
#include "overlays/positions.hpp"

namespace globe::overlays {
namespace {

using nlohmann::json;

// The deepest nesting of arrays and objects, strings skipped: checked before parsing so that a
// hostile file cannot exhaust the stack on the way in or out.
int jsonNesting(std::string_view text) {
  int depth = 0;
  int deepest = 0;
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        inString = false;
      }
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

// simplestyle-spec colours: "#rrggbb" or "#rgb" (the '#' optional).
std::optional<Rgba> parseHexColor(const json& value) {
  if (!value.is_string()) return std::nullopt;
  std::string_view text = value.get_ref<const std::string&>();
  if (!text.empty() && text.front() == '#') text.remove_prefix(1);
  if (text.size() != 6 && text.size() != 3) return std::nullopt;
  uint32_t rgb = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), rgb, 16);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if (text.size() == 3) {
    const auto nibble = [rgb](int shift) {
      return static_cast<uint8_t>(((rgb >> shift) & 0xfu) * 17);
    };
    return Rgba{nibble(8), nibble(4), nibble(0), 255};
  }
  return Rgba{static_cast<uint8_t>(rgb >> 16), static_cast<uint8_t>((rgb >> 8) & 0xffu),
              static_cast<uint8_t>(rgb & 0xffu), 255};
}

std::optional<double> number(const json& properties, const char* key) {
  const auto found = properties.find(key);
  if (found == properties.end() || !found->is_number()) return std::nullopt;
  const double value = found->get<double>();
  return std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
}

// A value for an error message: short, and safe whatever its strings hold.
std::string brief(const json& value) {
  return value.dump(-1, ' ', false, json::error_handler_t::replace).substr(0, 60);
}

uint8_t opacityByte(double opacity) {
  return static_cast<uint8_t>(std::lround(std::clamp(opacity, 0.0, 1.0) * 255));
}

// Without simplestyle properties, CesiumJS's GeoJSON defaults: yellow 2 px lines, yellow fill at
// 100/255 (Google Earth's white, opaque KML fill would hide the ground under every polygon).
Style simplestyle(const json& properties) {
  Style style;
  style.lineColor = {255, 255, 0, 255};
  style.lineWidthPixels = 2;
  style.polygonColor = {255, 255, 0, 100};
  if (!properties.is_object()) return style;
  const auto color = [&](const char* key) -> std::optional<Rgba> {
    const auto found = properties.find(key);
    return found == properties.end() ? std::nullopt : parseHexColor(*found);
  };
  if (auto stroke = color("stroke")) style.lineColor = *stroke;
  if (auto width = number(properties, "stroke-width"); width && *width >= 0) {
    style.lineWidthPixels = *width;
  }
  if (auto opacity = number(properties, "stroke-opacity"))
    style.lineColor.a = opacityByte(*opacity);
  if (auto fill = color("fill")) style.polygonColor = *fill;
  if (auto opacity = number(properties, "fill-opacity")) {
    style.polygonColor.a = opacityByte(*opacity);
  }
  if (auto marker = color("marker-color")) style.iconColor = *marker;
  return style;
}

std::string stringProperty(const json& properties, std::initializer_list<const char*> keys) {
  if (!properties.is_object()) return {};
  for (const char* key : keys) {
    const auto found = properties.find(key);
    if (found != properties.end() && found->is_string() &&
        !found->get_ref<const std::string&>().empty()) {
      return found->get<std::string>();
    }
  }
  return {};
}

class GeoJsonReader {
 public:
  explicit GeoJsonReader(const std::filesystem::path& file) : where_(file.string()) {
    document_.file = file;
  }

  Result<OverlayDocument> read(std::string_view text) {
    if (jsonNesting(text) > 4 * kMaxGeoJsonNesting) {
      return makeError(where_ + ": JSON nested deeper than " +
                       std::to_string(4 * kMaxGeoJsonNesting) + " levels");
    }
    json root;
    try {
      root = json::parse(text);
    } catch (const json::exception& e) {
      return makeError(where_ + ": not JSON (" + e.what() + ")");
    }
    if (!root.is_object() || !root.contains("type") || !root["type"].is_string()) {
      return makeError(where_ + ": not GeoJSON (no \"type\" member in a top-level object)");
    }
    if (auto name = root.find("name"); name != root.end() && name->is_string()) {
      document_.name = name->get<std::string>();
    }
    if (document_.name.empty()) document_.name = document_.file.filename().string();
    const std::string type = root["type"].get<std::string>();
    if (type == "FeatureCollection") {
      const auto features = root.find("features");
      if (features == root.end() || !features->is_array()) {
        return makeError(where_ + ": a FeatureCollection without a \"features\" array");
      }
      if (auto read = readFeatures(*features); !read) return Error{read.error()};
    } else if (type == "Feature") {
      if (auto feature = readLoneFeature(root); !feature) return Error{feature.error()};
    } else {
      Placemark placemark;
      if (auto geometry = readGeometry(root, "the geometry", 0, placemark.geometries); !geometry) {
        return Error{geometry.error()};
      }
      // A bare geometry: its vertices count as well.
      auto kept = placemark.geometries.empty()
                      ? Result<void>{}
                      : budget_.append(std::move(placemark), document_);
      if (!kept) return Error{kept.error()};
    }
    return std::move(document_);
  }

 private:
  // Reads one feature. What is wrong with it alone (not the budget's errors) is noted in
  // problems_ and leaves it out.
  Result<void> readFeature(const json& feature, size_t index) {
    std::string what = "feature " + std::to_string(index + 1);
    if (!feature.is_object() || feature.value("type", json()) != "Feature") {
      return leaveOut(where_ + ": " + what + " is not a Feature object");
    }
    static const json kNone;
    const auto properties = feature.find("properties");
    const json& props = properties != feature.end() ? *properties : kNone;
    Placemark placemark;
    placemark.name = stringProperty(props, {"name", "title", "NAME", "name_en"});
    placemark.description = stringProperty(props, {"description"});
    if (!placemark.name.empty()) what += " \"" + placemark.name.substr(0, 80) + "\"";
    const auto geometry = feature.find("geometry");
    if (geometry == feature.end() || geometry->is_null()) return {};
    if (auto read = readGeometry(*geometry, what, 0, placemark.geometries); !read) {
      return leaveOut(read.error());
    }
    if (placemark.geometries.empty()) return {};
    placemark.style = simplestyle(props);
    return budget_.append(std::move(placemark), document_);
  }

  Result<void> leaveOut(std::string problem) {
    problems_.push_back(std::move(problem));
    return {};
  }

  // A lone Feature: its problem is the file's.
  Result<void> readLoneFeature(const json& feature) {
    if (auto read = readFeature(feature, 0); !read) return read;
    if (!problems_.empty()) return makeError(problems_.front());
    return {};
  }

  // A collection's features. One that cannot be read is left out with a warning, as GDAL and
  // OpenLayers read the rest; the budget's errors end the reading; nothing readable at all is the
  // first problem's error.
  Result<void> readFeatures(const json& features) {
    for (size_t i = 0; i < features.size(); ++i) {
      if (auto feature = readFeature(features[i], i); !feature) return feature;
    }
    if (problems_.empty()) return {};
    if (document_.placemarks.empty()) return makeError(problems_.front());
    constexpr size_t kListed = 5;
    for (size_t k = 0; k < std::min(problems_.size(), kListed); ++k)
      document_.warnings.push_back(problems_[k] + "; feature left out");
    if (problems_.size() > kListed) {
      document_.warnings.push_back(where_ + ": " + std::to_string(problems_.size() - kListed) +
                                   " more features left out for the same kinds of problem");
    }
    return {};
  }

  Result<Position> position(const json& value, const std::string& what) const {
    if (!value.is_array() || value.size() < 2 || !value[0].is_number() || !value[1].is_number() ||
        (value.size() > 2 && !value[2].is_number())) {
      return makeError(where_ + ": " + what + ": a position " + brief(value) +
                       " is not [longitude, latitude(, height)]");
    }
    Position p{value[0].get<double>(), value[1].get<double>(),
               value.size() > 2 ? value[2].get<double>() : 0.0};
    if (auto problem = positionProblem(p)) {
      return makeError(where_ + ": " + what + ": position " + brief(value) + ": " + *problem);
    }
    return p;
  }

  Result<std::vector<Position>> positions(const json& value, const std::string& what) const {
    if (!value.is_array())
      return makeError(where_ + ": " + what + ": coordinates are not an array");
    std::vector<Position> out;
    out.reserve(value.size());
    for (const json& item : value) {
      auto p = position(item, what);
      if (!p) return Error{p.error()};
      out.push_back(*p);
    }
    return out;
  }

  Result<void> appendPolygon(const json& rings, const std::string& what,
                             std::vector<Geometry>& out) const {
    if (!rings.is_array())
      return makeError(where_ + ": " + what + ": a Polygon is not an array of rings");
    Geometry polygon;
    polygon.kind = GeometryKind::Polygon;
    for (const json& ringJson : rings) {
      auto ring = positions(ringJson, what);
      if (!ring) return Error{ring.error()};
      closeRing(*ring);
      if (isUsableRing(*ring)) {
        polygon.rings.push_back(std::move(*ring));
      } else if (polygon.rings.empty()) {
        return {};  // no usable outer ring: nothing to draw
      }
    }
    if (!polygon.rings.empty()) out.push_back(std::move(polygon));
    return {};
  }

  Result<void> appendLine(const json& coordinates, const std::string& what,
                          std::vector<Geometry>& out) const {
    auto line = positions(coordinates, what);
    if (!line) return Error{line.error()};
    if (line->size() < 2) return {};
    Geometry geometry;
    geometry.kind = GeometryKind::LineString;
    geometry.rings.push_back(std::move(*line));
    out.push_back(std::move(geometry));
    return {};
  }

  Result<void> readGeometry(const json& g, const std::string& what, int depth,
                            std::vector<Geometry>& out) const {
    if (!g.is_object() || !g.contains("type") || !g["type"].is_string()) {
      return makeError(where_ + ": " + what + ": a geometry without a \"type\"");
    }
    const std::string type = g["type"].get<std::string>();
    if (type == "GeometryCollection") {
      if (depth + 1 > kMaxGeoJsonNesting) {
        return makeError(where_ + ": " + what + ": GeometryCollections nested deeper than " +
                         std::to_string(kMaxGeoJsonNesting) + " levels");
      }
      const auto geometries = g.find("geometries");
      if (geometries == g.end() || !geometries->is_array()) {
        return makeError(where_ + ": " + what + ": a GeometryCollection without \"geometries\"");
      }
      for (const json& inner : *geometries) {
        if (auto read = readGeometry(inner, what, depth + 1, out); !read) return read;
      }
      return {};
    }
    const auto found = g.find("coordinates");
    if (found == g.end() || !found->is_array()) {
      return makeError(where_ + ": " + what + ": a " + type.substr(0, 40) +
                       " without a \"coordinates\" array");
    }
    const json& coordinates = *found;
    if (type == "Point") {
      if (coordinates.empty()) return {};  // an empty Point is allowed and draws nothing
      auto p = position(coordinates, what);
      if (!p) return Error{p.error()};
      out.push_back(
          Geometry{GeometryKind::Point, AltitudeMode::ClampToGround, false, false, {{*p}}});
    } else if (type == "MultiPoint") {
      auto points = positions(coordinates, what);
      if (!points) return Error{points.error()};
      for (const Position& p : *points) {
        out.push_back(
            Geometry{GeometryKind::Point, AltitudeMode::ClampToGround, false, false, {{p}}});
      }
    } else if (type == "LineString") {
      return appendLine(coordinates, what, out);
    } else if (type == "MultiLineString") {
      for (const json& line : coordinates) {
        if (auto read = appendLine(line, what, out); !read) return read;
      }
    } else if (type == "Polygon") {
      return appendPolygon(coordinates, what, out);
    } else if (type == "MultiPolygon") {
      for (const json& polygon : coordinates) {
        if (auto read = appendPolygon(polygon, what, out); !read) return read;
      }
    } else {
      return makeError(where_ + ": " + what + ": unknown geometry type \"" + type.substr(0, 40) +
                       "\"");
    }
    return {};
  }

  std::string where_;
  OverlayDocument document_;
  OverlayBudget budget_{where_};
  std::vector<std::string> problems_;  // the features left out, each with why
};

}  // namespace

Result<OverlayDocument> readGeoJsonText(std::string_view text, const std::filesystem::path& file) {
  return GeoJsonReader(file).read(text);
}

}  // namespace globe::overlays
