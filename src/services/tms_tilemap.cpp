#include "services/tms_tilemap.hpp"

#include <tinyxml2.h>

#include <cmath>
#include <cstring>
#include <numbers>

namespace globe::services {
namespace {

constexpr double kMercatorHalfWorld = std::numbers::pi * 6378137.0;

double attribute(const tinyxml2::XMLElement* e, const char* name, double fallback) {
  double value = fallback;
  if (e != nullptr) e->QueryDoubleAttribute(name, &value);
  return value;
}

double metersToLon(double x) { return x / kMercatorHalfWorld * 180; }
double metersToLat(double y) {
  return (2 * std::atan(std::exp(y / 6378137.0)) - std::numbers::pi / 2) * 180 / std::numbers::pi;
}

}  // namespace

Result<TmsTileMap> parseTmsTileMap(std::string_view xml, const std::string& name) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    return makeError(name + ": not XML (" + std::string(doc.ErrorStr()) + ")");
  }
  const tinyxml2::XMLElement* map = doc.FirstChildElement("TileMap");
  if (map == nullptr) return makeError(name + ": not a TMS tilemapresource.xml (no <TileMap>)");
  TmsTileMap out;
  const tinyxml2::XMLElement* srsElement = map->FirstChildElement("SRS");
  const std::string srs =
      srsElement != nullptr && srsElement->GetText() != nullptr ? srsElement->GetText() : "";
  if (srs == "EPSG:4326") {
    out.tiling.crs = TileCrs::Geographic;
  } else if (srs == "EPSG:3857" || srs == "EPSG:900913" || srs == "OSGEO:41001") {
    out.tiling.crs = TileCrs::WebMercator;
  } else {
    return makeError(name + ": SRS \"" + srs + "\" (EPSG:4326 or Web Mercator expected)");
  }
  if (const auto* t = map->FirstChildElement("Title"); t != nullptr && t->GetText() != nullptr)
    out.title = t->GetText();
  const auto* box = map->FirstChildElement("BoundingBox");
  const auto* origin = map->FirstChildElement("Origin");
  const auto* format = map->FirstChildElement("TileFormat");
  const auto* sets = map->FirstChildElement("TileSets");
  if (box == nullptr || origin == nullptr || format == nullptr || sets == nullptr) {
    return makeError(name + ": a TileMap without BoundingBox, Origin, TileFormat or TileSets");
  }
  const double minx = attribute(box, "minx", NAN), miny = attribute(box, "miny", NAN);
  const double maxx = attribute(box, "maxx", NAN), maxy = attribute(box, "maxy", NAN);
  const double ox = attribute(origin, "x", NAN), oy = attribute(origin, "y", NAN);
  const double tileWidth = attribute(format, "width", 256),
               tileHeight = attribute(format, "height", 256);
  if (!(minx < maxx && miny < maxy) || !std::isfinite(ox) || !std::isfinite(oy) ||
      !(tileWidth >= 16 && tileWidth <= 4096 && tileHeight >= 16 && tileHeight <= 4096)) {
    return makeError(name +
                     ": a TileMap with an empty box, no origin or a tile size outside 16..4096");
  }
  const char* extension = format->Attribute("extension");
  out.extension = extension != nullptr ? extension : "png";
  if (out.tiling.crs == TileCrs::Geographic) {
    out.bounds = {minx, miny, maxx, maxy};
  } else {
    out.bounds = {metersToLon(minx), metersToLat(miny), metersToLon(maxx), metersToLat(maxy)};
  }
  for (const auto* set = sets->FirstChildElement("TileSet"); set != nullptr;
       set = set->NextSiblingElement("TileSet")) {
    const char* href = set->Attribute("href");
    const double upp = attribute(set, "units-per-pixel", NAN);
    if (href == nullptr || !(upp > 0)) {
      return makeError(name + ": a TileSet without href or units-per-pixel");
    }
    TileMatrix m;
    m.id = set->Attribute("order") != nullptr ? set->Attribute("order") : href;
    m.unitsPerPixel = upp;
    m.tileWidth = static_cast<uint32_t>(tileWidth);
    m.tileHeight = static_cast<uint32_t>(tileHeight);
    // Rows count up from the origin (the bottom): the grid's top is whole tiles above it.
    const double columns = std::ceil((maxx - ox) / (upp * tileWidth) - 1e-6);
    const double rows = std::ceil((maxy - oy) / (upp * tileHeight) - 1e-6);
    if (!(columns >= 1 && rows >= 1 && columns < 1e9 && rows < 1e9)) {
      return makeError(name + ": tile set " + href + " has no whole tile in its box");
    }
    m.columns = static_cast<uint64_t>(columns);
    m.rows = static_cast<uint64_t>(rows);
    m.originX = ox;
    m.originY = oy + rows * upp * tileHeight;
    out.tiling.matrices.push_back(m);
    out.hrefs.emplace_back(href);
  }
  if (out.tiling.matrices.empty()) return makeError(name + ": no tile sets");
  for (size_t i = 1; i < out.tiling.matrices.size(); ++i) {
    if (!(out.tiling.matrices[i].unitsPerPixel < out.tiling.matrices[i - 1].unitsPerPixel)) {
      return makeError(name + ": tile sets not from coarse to fine");
    }
  }
  return out;
}

}  // namespace globe::services
