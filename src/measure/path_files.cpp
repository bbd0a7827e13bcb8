#include "measure/path_files.hpp"

#include <tinyxml2.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string_view>

#include "geo/elevation_limits.hpp"
#include "transport/atomic_file.hpp"

namespace globe::measure {
namespace {

constexpr uint64_t kMaxPathFileBytes = uint64_t{256} << 20;

// The element's local name (without a namespace prefix: "gx:coord" is "coord").
std::string_view localName(const tinyxml2::XMLElement* e) {
  std::string_view name = e->Name();
  const size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

const tinyxml2::XMLElement* firstDescendant(const tinyxml2::XMLElement* e, std::string_view name) {
  for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (localName(c) == name) return c;
    if (const auto* found = firstDescendant(c, name)) return found;
  }
  return nullptr;
}

void allDescendants(const tinyxml2::XMLElement* e, std::string_view name,
                    std::vector<const tinyxml2::XMLElement*>& out) {
  for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (localName(c) == name) out.push_back(c);
    allDescendants(c, name, out);
  }
}

// The points of the first of the root's `lineName` elements (trk, rte) that has two or more.
std::vector<const tinyxml2::XMLElement*> firstLineOf(const tinyxml2::XMLElement* root,
                                                     std::string_view lineName,
                                                     std::string_view pointName) {
  std::vector<const tinyxml2::XMLElement*> lines;
  allDescendants(root, lineName, lines);
  for (const tinyxml2::XMLElement* line : lines) {
    std::vector<const tinyxml2::XMLElement*> points;
    allDescendants(line, pointName, points);
    if (points.size() >= 2) return points;
  }
  return {};
}

Result<std::vector<PathPoint>> gpxLine(const tinyxml2::XMLElement* root, const std::string& where) {
  // The first track of two points or more, else the first such route (as gpxpy's users pick:
  // a device writes empty or one-point tracks before the one that matters).
  std::vector<const tinyxml2::XMLElement*> points = firstLineOf(root, "trk", "trkpt");
  if (points.empty()) points = firstLineOf(root, "rte", "rtept");
  std::vector<PathPoint> line;
  for (const tinyxml2::XMLElement* p : points) {
    PathPoint point;
    if (p->QueryDoubleAttribute("lat", &point.latitudeDegrees) != tinyxml2::XML_SUCCESS ||
        p->QueryDoubleAttribute("lon", &point.longitudeDegrees) != tinyxml2::XML_SUCCESS) {
      return makeError(where + ": line " + std::to_string(p->GetLineNum()) +
                       ": a point without lat and lon");
    }
    if (const auto* ele = p->FirstChildElement("ele")) {
      double value = 0;
      if (ele->QueryDoubleText(&value) == tinyxml2::XML_SUCCESS) point.elevationMeters = value;
    }
    line.push_back(point);
  }
  return line;
}

// "lon,lat[,alt] lon,lat[,alt] ..." (KML coordinates) or gx:coord's "lon lat alt".
Result<std::vector<PathPoint>> kmlLine(const tinyxml2::XMLElement* root, const std::string& where) {
  std::vector<PathPoint> line;
  if (const auto* lineString = firstDescendant(root, "LineString")) {
    const auto* coordinates = firstDescendant(lineString, "coordinates");
    std::istringstream in(coordinates && coordinates->GetText() ? coordinates->GetText() : "");
    std::string tuple;
    while (in >> tuple) {
      PathPoint p;
      char* end = nullptr;
      p.longitudeDegrees = std::strtod(tuple.c_str(), &end);
      if (*end != ',') return makeError(where + ": a LineString coordinate \"" + tuple + "\"");
      p.latitudeDegrees = std::strtod(end + 1, &end);
      if (*end == ',') p.elevationMeters = std::strtod(end + 1, &end);
      if (*end != '\0') return makeError(where + ": a LineString coordinate \"" + tuple + "\"");
      line.push_back(p);
    }
    return line;
  }
  std::vector<const tinyxml2::XMLElement*> coords;
  allDescendants(root, "coord", coords);  // gx:Track
  for (const tinyxml2::XMLElement* c : coords) {
    PathPoint p;
    std::istringstream in(c->GetText() ? c->GetText() : "");
    if (!(in >> p.longitudeDegrees >> p.latitudeDegrees)) {
      return makeError(where + ": line " + std::to_string(c->GetLineNum()) + ": a gx:coord");
    }
    if (double alt = 0; in >> alt) p.elevationMeters = alt;
    line.push_back(p);
  }
  return line;
}

Result<std::vector<PathPoint>> geoJsonLine(const nlohmann::json& json, const std::string& where) {
  const auto fromPositions =
      [&](const nlohmann::json& positions) -> Result<std::vector<PathPoint>> {
    std::vector<PathPoint> line;
    for (const auto& position : positions) {
      if (!position.is_array() || position.size() < 2 || !position[0].is_number() ||
          !position[1].is_number()) {
        return makeError(where + ": a LineString position is not [lon, lat(, elevation)]");
      }
      PathPoint p{position[0].get<double>(), position[1].get<double>()};
      if (position.size() > 2 && position[2].is_number())
        p.elevationMeters = position[2].get<double>();
      line.push_back(p);
    }
    return line;
  };
  const auto fromGeometry =
      [&](const nlohmann::json& g) -> std::optional<Result<std::vector<PathPoint>>> {
    if (!g.is_object() || !g.contains("type")) return std::nullopt;
    if (g["type"] == "LineString" && g.contains("coordinates"))
      return fromPositions(g["coordinates"]);
    if (g["type"] == "MultiLineString" && g.contains("coordinates") &&
        g["coordinates"].is_array()) {
      std::vector<PathPoint> all;
      for (const auto& part : g["coordinates"]) {
        auto line = fromPositions(part);
        if (!line) return line;
        all.insert(all.end(), line->begin(), line->end());
      }
      return Result<std::vector<PathPoint>>(std::move(all));
    }
    return std::nullopt;
  };
  if (json.value("type", "") == "FeatureCollection" && json.contains("features")) {
    for (const auto& feature : json["features"]) {
      if (feature.is_object() && feature.contains("geometry")) {
        if (auto line = fromGeometry(feature["geometry"])) return std::move(*line);
      }
    }
    return std::vector<PathPoint>();
  }
  if (json.value("type", "") == "Feature" && json.contains("geometry")) {
    if (auto line = fromGeometry(json["geometry"])) return std::move(*line);
    return std::vector<PathPoint>();
  }
  if (auto line = fromGeometry(json)) return std::move(*line);
  return std::vector<PathPoint>();
}

// Elevations no path has (geo/elevation_limits.hpp) are read as not given, with one warning.
void dropImpossibleElevations(std::vector<PathPoint>& line, const std::string& where,
                              const core::WarningSink& warnings) {
  size_t dropped = 0;
  std::string first;
  for (size_t k = 0; k < line.size(); ++k) {
    double& e = line[k].elevationMeters;
    if (std::isnan(e) || geo::isPossibleElevationMeters(e)) continue;
    if (dropped++ == 0) first = std::to_string(e) + " at point " + std::to_string(k + 1);
    e = std::numeric_limits<double>::quiet_NaN();
  }
  if (dropped > 0) {
    core::warn(warnings,
               where + ": " + std::to_string(dropped) + " of " + std::to_string(line.size()) +
                   " elevations outside -12000..100000 m (" + first + ") read as not given");
  }
}

}  // namespace

Result<std::vector<PathPoint>> readPathFile(const std::filesystem::path& file,
                                            const core::WarningSink& warnings) {
  const std::string where = file.string();
  auto bytes = transport::readWholeFile(file, kMaxPathFileBytes);
  if (!bytes) return Error{bytes.error()};
  const std::string text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
  Result<std::vector<PathPoint>> line = std::vector<PathPoint>();
  const size_t first = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
  if (first != std::string::npos && text[first] == '<') {
    tinyxml2::XMLDocument document;
    if (document.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS ||
        document.RootElement() == nullptr) {
      return makeError(where + ": not XML (" + std::string(document.ErrorStr()) + ")");
    }
    const tinyxml2::XMLElement* root = document.RootElement();
    if (localName(root) == "gpx") {
      line = gpxLine(root, where);
    } else if (localName(root) == "kml") {
      line = kmlLine(root, where);
    } else {
      return makeError(where + ": an XML file that is neither GPX nor KML (<" +
                       std::string(root->Name()) + ">)");
    }
  } else {
    const auto json = nlohmann::json::parse(text, nullptr, false);
    if (json.is_discarded() || !json.is_object()) {
      return makeError(where + ": neither GPX, KML nor GeoJSON");
    }
    line = geoJsonLine(json, where);
  }
  if (!line) return line;
  if (line->size() < 2) {
    return makeError(where +
                     ": no line of two points or more (a GPX track or route, a KML or "
                     "GeoJSON LineString)");
  }
  for (const PathPoint& p : *line) {
    if (!(std::fabs(p.latitudeDegrees) <= 90) || !(std::fabs(p.longitudeDegrees) <= 180)) {
      return makeError(where + ": a point outside -180..180, -90..90 degrees");
    }
  }
  dropImpossibleElevations(*line, where, warnings);
  return line;
}

}  // namespace globe::measure
