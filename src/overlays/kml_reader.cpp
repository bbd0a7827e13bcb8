#include "overlays/kml_reader.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <iterator>

#include <cmath>
#include <limits>
#include <string>

#include "overlays/kml_color.hpp"
#include "overlays/kml_coordinates.hpp"
#include "overlays/kml_style.hpp"
#include "overlays/overlay_budget.hpp"
#include "overlays/positions.hpp"
#include "overlays/xml_elements.hpp"

namespace globe::overlays {
namespace {

using tinyxml2::XMLElement;

std::string lineOf(const XMLElement& e) { return "line " + std::to_string(e.GetLineNum()); }

// How errors name a feature: `placemark "Name" (line 12)`.
std::string label(const XMLElement& feature) {
  const std::string kind = std::string(localName(feature)) == "Placemark"
                               ? "placemark"
                               : std::string(localName(feature));
  const std::string name = childText(feature, "name").value_or("");
  if (name.empty()) return kind + " at " + lineOf(feature);
  return kind + " \"" + name.substr(0, 80) + "\" (" + lineOf(feature) + ")";
}

bool visibility(const XMLElement& feature) {
  const auto text = childText(feature, "visibility");
  return !text || parseBoolean(*text).value_or(true);
}

AltitudeMode altitudeModeOf(const XMLElement& geometry, AltitudeMode fallback) {
  // kml:altitudeMode and gx:altitudeMode share the local name.
  const std::string mode = childText(geometry, "altitudeMode").value_or("");
  if (mode == "clampToGround" || mode == "clampToSeaFloor") return AltitudeMode::ClampToGround;
  if (mode == "relativeToGround" || mode == "relativeToSeaFloor") {
    return AltitudeMode::RelativeToGround;
  }
  if (mode == "absolute") return AltitudeMode::Absolute;
  return fallback;
}

bool flag(const XMLElement& geometry, std::string_view name) {
  const auto text = childText(geometry, name);
  return text && parseBoolean(*text).value_or(false);
}

class KmlReader {
 public:
  KmlReader(const std::filesystem::path& file, OverlayImages& images)
      : where_(file.string()), images_(images) {
    document_.file = file;
  }

  Result<OverlayDocument> read(std::string_view text) {
    tinyxml2::XMLDocument xml;
    auto parsed = parseRootElement(xml, text, where_, "kml", "KML");
    if (!parsed) return Error{parsed.error()};
    const XMLElement* root = *parsed;
    if (auto collected = collectStyles(*root, 0); !collected) return Error{collected.error()};
    if (auto features = readContainer(*root, "", true, 0, true); !features) {
      return Error{features.error()};
    }
    if (document_.name.empty()) document_.name = document_.file.filename().string();
    return std::move(document_);
  }

 private:
  Error tooDeep(const XMLElement& e, std::string_view what) const {
    return makeError(where_ + ": " + std::string(what) + " nested deeper than " +
                     std::to_string(kMaxKmlNesting) + " levels (" + lineOf(e) + ")");
  }

  // Shared styles live in Documents (and, against the spec but in real files, in Folders).
  Result<void> collectStyles(const XMLElement& container, int depth) {
    for (const auto* c = container.FirstChildElement(); c; c = c->NextSiblingElement()) {
      const std::string_view name = localName(*c);
      if (name == "Style" || name == "StyleMap") styles_.add(*c);
      if (name == "Document" || name == "Folder") {
        if (depth + 1 > kMaxKmlNesting) return tooDeep(*c, "Folders and Documents");
        if (auto inner = collectStyles(*c, depth + 1); !inner) return inner;
      }
    }
    return {};
  }

  // The features of a Document, Folder or the <kml> root. The root's own Document is not a
  // folder: its name is the document's.
  Result<void> readContainer(const XMLElement& container, const std::string& folderPath,
                             bool visible, int depth, bool isRoot) {
    for (const auto* c = container.FirstChildElement(); c; c = c->NextSiblingElement()) {
      const std::string_view name = localName(*c);
      if (name == "Document" || name == "Folder") {
        if (depth + 1 > kMaxKmlNesting) return tooDeep(*c, "Folders and Documents");
        const std::string title = childText(*c, "name").value_or("");
        std::string path = folderPath;
        if (isRoot && name == "Document") {
          if (document_.name.empty()) document_.name = title;
        } else if (!title.empty()) {
          path = path.empty() ? title : path + "/" + title;
        }
        auto inner = readContainer(*c, path, visible && visibility(*c), depth + 1, false);
        if (!inner) return inner;
      } else if (name == "Placemark") {
        if (auto placemark = readPlacemark(*c, folderPath, visible); !placemark) return placemark;
      } else if (name == "GroundOverlay") {
        if (auto overlay = readGroundOverlay(*c, visible); !overlay) return overlay;
      }
    }
    return {};
  }

  Result<void> readPlacemark(const XMLElement& e, const std::string& folderPath, bool visible) {
    Placemark placemark;
    for (const auto* c = e.FirstChildElement(); c; c = c->NextSiblingElement()) {
      auto geometry = readGeometry(*c, e, AltitudeMode::ClampToGround, 0, placemark.geometries);
      if (!geometry) return geometry;
    }
    if (placemark.geometries.empty()) return {};
    placemark.name = childText(e, "name").value_or("");
    if (const auto* description = child(e, "description")) {
      placemark.description = textOf(*description);
    }
    const XMLElement* inlineStyle = child(e, "Style");
    if (inlineStyle == nullptr) inlineStyle = child(e, "StyleMap");
    placemark.style = styles_.resolve(childText(e, "styleUrl").value_or(""), inlineStyle, images_);
    placemark.visible = visible && visibility(e);
    placemark.folderPath = folderPath;
    return budget_.append(std::move(placemark), document_);
  }

  Result<std::vector<Position>> coordinates(const XMLElement& geometry,
                                            const XMLElement& placemark) const {
    const auto* element = child(geometry, "coordinates");
    if (element == nullptr) return std::vector<Position>();
    auto positions = parseKmlCoordinates(textOf(*element));
    if (!positions) {
      return makeError(where_ + ": " + label(placemark) + ": " + std::string(localName(geometry)) +
                       " " + positions.error());
    }
    return positions;
  }

  // The positions of a Polygon boundary's LinearRings, closed; unusable rings dropped.
  Result<void> appendRings(const XMLElement& boundary, const XMLElement& placemark,
                           std::vector<std::vector<Position>>& rings) const {
    for (const auto* r = boundary.FirstChildElement(); r; r = r->NextSiblingElement()) {
      if (localName(*r) != "LinearRing") continue;
      auto ring = coordinates(*r, placemark);
      if (!ring) return Error{ring.error()};
      closeRing(*ring);
      if (isUsableRing(*ring)) rings.push_back(std::move(*ring));
    }
    return {};
  }

  // Appends what `e` draws, if it is a geometry (anything else is not, and adds nothing).
  Result<void> readGeometry(const XMLElement& e, const XMLElement& placemark,
                            AltitudeMode inherited, int depth, std::vector<Geometry>& out) const {
    const std::string_view name = localName(e);
    Geometry geometry;
    geometry.altitudeMode = altitudeModeOf(e, inherited);
    geometry.extrude = flag(e, "extrude");
    geometry.tessellate = flag(e, "tessellate");
    // MultiPolygon, MultiLineString and MultiPoint are not KML, but tools write them (GDAL's
    // issue 4031, its non_conformant_multi.kml) and GDAL reads them as MultiGeometry: so does this.
    static constexpr std::string_view kContainers[] = {
        "MultiGeometry", "MultiTrack", "MultiPolygon", "MultiLineString", "MultiPoint"};
    if (std::find(std::begin(kContainers), std::end(kContainers), name) != std::end(kContainers)) {
      if (depth + 1 > kMaxKmlNesting) return tooDeep(e, std::string(name) + " elements");
      for (const auto* c = e.FirstChildElement(); c; c = c->NextSiblingElement()) {
        auto inner = readGeometry(*c, placemark, geometry.altitudeMode, depth + 1, out);
        if (!inner) return inner;
      }
    } else if (name == "Point" || name == "LineString" || name == "LinearRing") {
      auto positions = coordinates(e, placemark);
      if (!positions) return Error{positions.error()};
      if (name == "Point") {
        if (positions->empty()) return {};
        positions->resize(1);
      } else {
        geometry.kind = GeometryKind::LineString;
        if (name == "LinearRing") closeRing(*positions);
        if (positions->size() < 2) return {};
      }
      geometry.rings.push_back(std::move(*positions));
      out.push_back(std::move(geometry));
    } else if (name == "Polygon") {
      geometry.kind = GeometryKind::Polygon;
      const auto* outer = child(e, "outerBoundaryIs");
      if (outer == nullptr) return {};
      if (auto ring = appendRings(*outer, placemark, geometry.rings); !ring) return ring;
      if (geometry.rings.size() != 1) return {};  // no usable outer ring
      for (const auto* c = e.FirstChildElement(); c; c = c->NextSiblingElement()) {
        if (localName(*c) != "innerBoundaryIs") continue;
        if (auto rings = appendRings(*c, placemark, geometry.rings); !rings) return rings;
      }
      out.push_back(std::move(geometry));
    } else if (name == "Track") {
      geometry.kind = GeometryKind::LineString;
      std::vector<Position> line;
      for (const auto* c = e.FirstChildElement(); c; c = c->NextSiblingElement()) {
        if (localName(*c) != "coord") continue;
        auto position = parseGxCoord(textOf(*c));
        if (!position) {
          return makeError(where_ + ": " + label(placemark) + ": " + lineOf(*c) + ": " +
                           position.error());
        }
        line.push_back(*position);
      }
      if (line.size() < 2) return {};
      geometry.rings.push_back(std::move(line));
      out.push_back(std::move(geometry));
    }
    return {};
  }

  Result<void> readGroundOverlay(const XMLElement& e, bool visible) {
    const auto* box = child(e, "LatLonBox");
    if (box == nullptr) return {};  // gx:LatLonQuad is not supported
    GroundOverlay overlay;
    overlay.name = childText(e, "name").value_or("");
    if (const auto* description = child(e, "description"))
      overlay.description = textOf(*description);
    overlay.visible = visible && visibility(e);
    if (auto color = parseKmlColor(childText(e, "color").value_or(""))) overlay.color = *color;
    if (auto order = parseNumber(childText(e, "drawOrder").value_or(""))) {
      // Clamped into int range (NaN stays 0).
      if (*order >= -1e9 && *order <= 1e9) overlay.drawOrder = static_cast<int>(*order);
    }
    const struct {
      const char* name;
      double* value;
      double limit;
    } edges[] = {{"north", &overlay.northDegrees, 90},
                 {"south", &overlay.southDegrees, 90},
                 {"east", &overlay.eastDegrees, 180},
                 {"west", &overlay.westDegrees, 180},
                 {"rotation", &overlay.rotationDegrees, 360}};
    for (const auto& edge : edges) {
      const auto text = childText(*box, edge.name);
      if (!text) continue;
      const auto value = parseNumber(*text);
      if (!value || !(std::fabs(*value) <= edge.limit)) {
        return makeError(where_ + ": " + label(e) + ": LatLonBox " + edge.name + " \"" +
                         text->substr(0, 40) + "\" is not a number within -" +
                         std::to_string(static_cast<int>(edge.limit)) + ".." +
                         std::to_string(static_cast<int>(edge.limit)));
      }
      *edge.value = *value;
    }
    if (const auto* icon = child(e, "Icon")) {
      ResolvedImage image = images_.resolve(childText(*icon, "href").value_or(""));
      overlay.imageHref = std::move(image.href);
      overlay.image = std::move(image.image);
    }
    document_.groundOverlays.push_back(std::move(overlay));
    return {};
  }

  std::string where_;
  OverlayImages& images_;
  KmlStyles styles_;
  OverlayDocument document_;
  OverlayBudget budget_{where_};
};

}  // namespace

Result<OverlayDocument> readKmlText(std::string_view text, const std::filesystem::path& file,
                                    OverlayImages& images) {
  auto document = KmlReader(file, images).read(text);
  if (document) {
    for (const std::string& warning : images.warnings()) {
      document->warnings.push_back(file.string() + ": " + warning);
    }
  }
  return document;
}

}  // namespace globe::overlays
