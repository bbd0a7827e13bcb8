#include "overlays/gpx_reader.hpp"

#include <tinyxml2.h>

#include <string>

#include "geo/elevation_limits.hpp"
#include "overlays/overlay_budget.hpp"
#include "overlays/positions.hpp"
#include "overlays/xml_elements.hpp"

namespace globe::overlays {
namespace {

using tinyxml2::XMLElement;

class GpxReader {
 public:
  explicit GpxReader(const std::filesystem::path& file) : where_(file.string()) {
    document_.file = file;
  }

  Result<OverlayDocument> read(std::string_view text) {
    tinyxml2::XMLDocument xml;
    auto parsed = parseRootElement(xml, text, where_, "gpx", "GPX");
    if (!parsed) return Error{parsed.error()};
    const XMLElement* root = *parsed;
    const XMLElement* metadata = child(*root, "metadata");  // GPX 1.1; 1.0 names the root
    document_.name = childText(metadata != nullptr ? *metadata : *root, "name").value_or("");
    if (document_.name.empty()) document_.name = document_.file.filename().string();
    for (const auto* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
      const std::string_view name = localName(*e);
      Result<void> read;
      if (name == "wpt") read = readWaypoint(*e);
      if (name == "rte") read = readLines(*e, false);
      if (name == "trk") read = readLines(*e, true);
      if (!read) return Error{read.error()};
    }
    if (impossibleElevations_ > 0) {
      document_.warnings.push_back(where_ + ": " + std::to_string(impossibleElevations_) +
                                   " elevations outside -12000..100000 m or not numbers, "
                                   "read as not given");
    }
    return std::move(document_);
  }

 private:
  Result<Position> point(const XMLElement& e) {
    Position p;
    const auto lat = parseNumber(e.Attribute("lat") != nullptr ? e.Attribute("lat") : "");
    const auto lon = parseNumber(e.Attribute("lon") != nullptr ? e.Attribute("lon") : "");
    if (!lat || !lon) {
      return makeError(where_ + ": line " + std::to_string(e.GetLineNum()) + ": a <" +
                       std::string(localName(e)) + "> without numeric lat and lon");
    }
    p.latitudeDegrees = *lat;
    p.longitudeDegrees = *lon;
    // An elevation no track has (1e308, NaN: written where a device had none) is not given;
    // GPX is drawn on the ground, so it only keeps the file from being read.
    if (auto ele = parseNumber(childText(e, "ele").value_or(""))) {
      if (geo::isPossibleElevationMeters(*ele)) {
        p.heightMeters = *ele;
      } else {
        ++impossibleElevations_;
      }
    }
    if (auto problem = positionProblem(p)) {
      return makeError(where_ + ": line " + std::to_string(e.GetLineNum()) + ": a <" +
                       std::string(localName(e)) + ">'s " + *problem);
    }
    return p;
  }

  static void describe(const XMLElement& e, Placemark& placemark) {
    placemark.name = childText(e, "name").value_or("");
    if (const auto* desc = child(e, "desc")) placemark.description = textOf(*desc);
  }

  Result<void> readWaypoint(const XMLElement& e) {
    auto p = point(e);
    if (!p) return Error{p.error()};
    Placemark placemark;
    describe(e, placemark);
    placemark.geometries.push_back(
        Geometry{GeometryKind::Point, AltitudeMode::ClampToGround, false, false, {{*p}}});
    return budget_.append(std::move(placemark), document_);
  }

  // A line of the element's children named pointName; fewer than two points add nothing.
  Result<void> appendLine(const XMLElement& parent, std::string_view pointName,
                          std::vector<Geometry>& out) {
    std::vector<Position> line;
    for (const auto* c = parent.FirstChildElement(); c; c = c->NextSiblingElement()) {
      if (localName(*c) != pointName) continue;
      auto p = point(*c);
      if (!p) return Error{p.error()};
      line.push_back(*p);
    }
    if (line.size() >= 2) {
      out.push_back(Geometry{
          GeometryKind::LineString, AltitudeMode::ClampToGround, false, false, {std::move(line)}});
    }
    return {};
  }

  // A track (one LineString per segment) or a route.
  Result<void> readLines(const XMLElement& e, bool track) {
    Placemark placemark;
    describe(e, placemark);
    // GPX carries no style: a bright 3 px line that shows over imagery and terrain alike.
    placemark.style.lineColor = {255, 64, 0, 255};
    placemark.style.lineWidthPixels = 3;
    if (track) {
      for (const auto* c = e.FirstChildElement(); c; c = c->NextSiblingElement()) {
        if (localName(*c) != "trkseg") continue;
        if (auto line = appendLine(*c, "trkpt", placemark.geometries); !line) return line;
      }
    } else if (auto line = appendLine(e, "rtept", placemark.geometries); !line) {
      return line;
    }
    if (placemark.geometries.empty()) return {};
    return budget_.append(std::move(placemark), document_);
  }

  std::string where_;
  size_t impossibleElevations_ = 0;
  OverlayDocument document_;
  OverlayBudget budget_{where_};
};

}  // namespace

Result<OverlayDocument> readGpxText(std::string_view text, const std::filesystem::path& file) {
  return GpxReader(file).read(text);
}

}  // namespace globe::overlays
