#include "services/tms_tilemap.hpp"

#include <tinyxml2.h>

#include <cmath>
#include <cstring>
#include <initializer_list>
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

// A TileMap's box and origin as written: x, y in the SRS's units, or degrees.
struct TileMapBox {
  double minx, miny, maxx, maxy, ox, oy;
};

// gdal2tiles 1.x wrote the box and origin in degrees, latitude first (south, west, north, east),
// whatever the SRS: a geodetic tree's box then has "longitudes" of ±180 as y, and a Web Mercator
// tree's box is a few "metres" wide at 0°, 0°. CesiumJS reads such trees with flipXY; so does this,
// told by the numbers: a Mercator box smaller than one pixel of the coarsest tile set is in degrees
// (in gdal2tiles' order unless that puts a latitude beyond ±90), and a geodetic box whose y
// reaches beyond ±90 while its x does not is flipped. Returns the box in the SRS's units, with the
// whole world's grid origin for a Mercator box that was in degrees (gdal2tiles' tiles are the
// global grid's), and the bounds in degrees.
TileMapBox normalizedBox(TileMapBox b, TileCrs crs, double coarsestTileSpan,
                         formats::BoundsDegrees& boundsDegrees) {
  const auto within = [](double limit, std::initializer_list<double> values) {
    for (double v : values)
      if (!(std::fabs(v) <= limit)) return false;
    return true;
  };
  const auto flip = [](TileMapBox x) {
    return TileMapBox{x.miny, x.minx, x.maxy, x.maxx, x.oy, x.ox};
  };
  if (crs == TileCrs::Geographic) {
    if (!within(90, {b.miny, b.maxy, b.oy}) && within(90, {b.minx, b.maxx, b.ox}) &&
        within(180, {b.miny, b.maxy, b.oy})) {
      b = flip(b);
    }
    boundsDegrees = {b.minx, b.miny, b.maxx, b.maxy};
    return b;
  }
  const bool degrees =
      within(180, {b.minx, b.miny, b.maxx, b.maxy}) && b.maxx - b.minx < coarsestTileSpan / 1e3;
  if (!degrees) {
    boundsDegrees = {metersToLon(b.minx), metersToLat(b.miny), metersToLon(b.maxx),
                     metersToLat(b.maxy)};
    return b;
  }
  if (within(90, {b.minx, b.maxx})) b = flip(b);  // gdal2tiles' order: latitude first
  boundsDegrees = {b.minx, b.miny, b.maxx, b.maxy};
  return {-kMercatorHalfWorld, -kMercatorHalfWorld, kMercatorHalfWorld,
          kMercatorHalfWorld,  -kMercatorHalfWorld, -kMercatorHalfWorld};
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
  const TileMapBox written{attribute(box, "minx", NAN), attribute(box, "miny", NAN),
                           attribute(box, "maxx", NAN), attribute(box, "maxy", NAN),
                           attribute(origin, "x", NAN), attribute(origin, "y", NAN)};
  const double tileWidth = attribute(format, "width", 256),
               tileHeight = attribute(format, "height", 256);
  if (!(written.minx < written.maxx && written.miny < written.maxy) || !std::isfinite(written.ox) ||
      !std::isfinite(written.oy) ||
      !(tileWidth >= 16 && tileWidth <= 4096 && tileHeight >= 16 && tileHeight <= 4096)) {
    return makeError(name +
                     ": a TileMap with an empty box, no origin or a tile size outside 16..4096");
  }
  const char* extension = format->Attribute("extension");
  out.extension = extension != nullptr ? extension : "png";
  const auto* firstSet = sets->FirstChildElement("TileSet");
  const TileMapBox b = normalizedBox(
      written, out.tiling.crs, attribute(firstSet, "units-per-pixel", NAN) * tileWidth, out.bounds);
  const double maxx = b.maxx, maxy = b.maxy, ox = b.ox, oy = b.oy;
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
