#include "services/wmts_capabilities.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace globe::services {
namespace {

using tinyxml2::XMLElement;

// Metres per degree a server may have meant in a longitude/latitude set's scale denominators:
// OGC's (WMTS 1.0.0, 6.1: the WGS84 equator), then OpenLayers' (a 6,370,997 m sphere), which
// NASA GIBS and others write theirs for.
constexpr double kMetersPerDegreeCandidates[] = {6378137.0 * 2 * 3.141592653589793 / 360,
                                                 6370997.0 * 2 * 3.141592653589793 / 360};

// A tiling's resolution is a short binary fraction of a degree (0.5625, 1.40625, 0.703125):
// true when within 1e-6 of one with at most 12 significant bits.
bool roundResolution(double degrees) {
  int exponent = 0;
  const double mantissa = std::frexp(degrees, &exponent) * 4096;
  return std::fabs(mantissa - std::round(mantissa)) < 4096 * 1e-6;
}
constexpr double kPixelMeters = 0.28e-3;  // the standard rendering pixel

const char* localName(const XMLElement* e) {
  const char* name = e->Name();
  const char* colon = std::strrchr(name, ':');
  return colon != nullptr ? colon + 1 : name;
}

const XMLElement* child(const XMLElement* e, const char* name) {
  if (e == nullptr) return nullptr;
  for (const XMLElement* c = e->FirstChildElement(); c != nullptr; c = c->NextSiblingElement())
    if (std::strcmp(localName(c), name) == 0) return c;
  return nullptr;
}

std::vector<const XMLElement*> children(const XMLElement* e, const char* name) {
  std::vector<const XMLElement*> out;
  if (e == nullptr) return out;
  for (const XMLElement* c = e->FirstChildElement(); c != nullptr; c = c->NextSiblingElement())
    if (std::strcmp(localName(c), name) == 0) out.push_back(c);
  return out;
}

std::string text(const XMLElement* e) {
  if (e == nullptr || e->GetText() == nullptr) return "";
  std::string s = e->GetText();
  const size_t first = s.find_first_not_of(" \t\r\n");
  const size_t last = s.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? "" : s.substr(first, last - first + 1);
}

bool twoNumbers(const std::string& s, double& a, double& b) {
  std::istringstream in(s);
  return static_cast<bool>(in >> a >> b);
}

// A tile matrix set's CRS: Web Mercator, or longitude/latitude (and whether its corners are
// written latitude first, as EPSG:4326's axis order says).
bool crsOf(const std::string& crs, TileCrs& kind, bool& latitudeFirst) {
  latitudeFirst = false;
  if (crs.find("3857") != std::string::npos || crs.find("900913") != std::string::npos ||
      crs.find("3785") != std::string::npos) {
    kind = TileCrs::WebMercator;
    return true;
  }
  if (crs.find("CRS84") != std::string::npos) {
    kind = TileCrs::Geographic;
    return true;
  }
  if (crs.find("4326") != std::string::npos) {
    kind = TileCrs::Geographic;
    latitudeFirst = true;
    return true;
  }
  return false;
}

}  // namespace

Result<WmtsCapabilities> parseWmtsCapabilities(std::string_view xml, const std::string& name) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    return makeError(name + ": not XML (" + std::string(doc.ErrorStr()) + ")");
  }
  const XMLElement* root = doc.RootElement();
  if (root == nullptr || std::strcmp(localName(root), "Capabilities") != 0) {
    return makeError(name + ": not a WMTS GetCapabilities document (no <Capabilities>)");
  }
  WmtsCapabilities caps;
  caps.title = text(child(child(root, "ServiceIdentification"), "Title"));
  for (const XMLElement* op : children(child(root, "OperationsMetadata"), "Operation")) {
    if (op->Attribute("name") == nullptr || std::strcmp(op->Attribute("name"), "GetTile") != 0)
      continue;
    for (const XMLElement* get : children(child(child(op, "DCP"), "HTTP"), "Get")) {
      bool kvp = true;  // unless its constraint says otherwise
      for (const XMLElement* constraint : children(get, "Constraint")) {
        kvp = false;
        for (const XMLElement* v : children(child(constraint, "AllowedValues"), "Value"))
          if (text(v) == "KVP") kvp = true;
      }
      const char* href = get->Attribute("xlink:href");
      if (kvp && href != nullptr && caps.kvpGetTileUrl.empty()) caps.kvpGetTileUrl = href;
    }
  }
  const XMLElement* contents = child(root, "Contents");
  if (contents == nullptr) return makeError(name + ": no <Contents>");
  for (const XMLElement* set : children(contents, "TileMatrixSet")) {
    const std::string id = text(child(set, "Identifier"));
    TileMatrixSet tiling;
    bool latitudeFirst = false;
    if (!crsOf(text(child(set, "SupportedCRS")), tiling.crs, latitudeFirst)) continue;
    // Which metres per degree its scales were written with: the one that makes them round.
    double metersPerUnit = 1.0;
    if (tiling.crs == TileCrs::Geographic) {
      metersPerUnit = kMetersPerDegreeCandidates[0];
      for (double candidate : kMetersPerDegreeCandidates) {
        bool allRound = true;
        for (const XMLElement* m : children(set, "TileMatrix")) {
          const double scale = std::atof(text(child(m, "ScaleDenominator")).c_str());
          allRound = allRound && roundResolution(scale * kPixelMeters / candidate);
        }
        if (allRound) {
          metersPerUnit = candidate;
          break;
        }
      }
    }
    bool valid = true;
    for (const XMLElement* m : children(set, "TileMatrix")) {
      TileMatrix matrix;
      matrix.id = text(child(m, "Identifier"));
      const double scale = std::atof(text(child(m, "ScaleDenominator")).c_str());
      double a = 0, b = 0;
      const bool corner = twoNumbers(text(child(m, "TopLeftCorner")), a, b);
      // EPSG:4326 corners come latitude first, CRS84's longitude first, unless a server wrote
      // them the other way: a first value beyond ±90 is a longitude, and so is a second one
      // (CRS84 sets written "90 -180", as OpenLayers and GDAL read them).
      const bool lonLatCrs = tiling.crs == TileCrs::Geographic && !latitudeFirst;
      const bool swap = (latitudeFirst && !(std::fabs(a) > 90)) ||
                        (lonLatCrs && std::fabs(b) > 90 && std::fabs(a) <= 90);
      matrix.originX = swap ? b : a;
      matrix.originY = swap ? a : b;
      matrix.unitsPerPixel = scale * kPixelMeters / metersPerUnit;
      const long width = std::atol(text(child(m, "TileWidth")).c_str());
      const long height = std::atol(text(child(m, "TileHeight")).c_str());
      const long long columns = std::atoll(text(child(m, "MatrixWidth")).c_str());
      const long long rows = std::atoll(text(child(m, "MatrixHeight")).c_str());
      if (!corner || !(matrix.unitsPerPixel > 0) || width < 16 || width > 4096 || height < 16 ||
          height > 4096 || columns < 1 || rows < 1 || columns > (1LL << 31) || rows > (1LL << 31)) {
        valid = false;
        break;
      }
      matrix.tileWidth = static_cast<uint32_t>(width);
      matrix.tileHeight = static_cast<uint32_t>(height);
      matrix.columns = static_cast<uint64_t>(columns);
      matrix.rows = static_cast<uint64_t>(rows);
      tiling.matrices.push_back(matrix);
    }
    if (!valid || tiling.matrices.empty()) continue;
    std::stable_sort(
        tiling.matrices.begin(), tiling.matrices.end(),
        [](const TileMatrix& x, const TileMatrix& y) { return x.unitsPerPixel > y.unitsPerPixel; });
    caps.tileMatrixSets.emplace(id, std::move(tiling));
  }
  for (const XMLElement* l : children(contents, "Layer")) {
    WmtsLayer layer;
    layer.identifier = text(child(l, "Identifier"));
    layer.title = text(child(l, "Title"));
    for (const XMLElement* f : children(l, "Format")) layer.formats.push_back(text(f));
    for (const XMLElement* s : children(l, "Style")) {
      const std::string id = text(child(s, "Identifier"));
      const char* isDefault = s->Attribute("isDefault");
      if (isDefault != nullptr && std::strcmp(isDefault, "true") == 0) {
        layer.styles.insert(layer.styles.begin(), id);
      } else {
        layer.styles.push_back(id);
      }
    }
    for (const XMLElement* link : children(l, "TileMatrixSetLink"))
      layer.tileMatrixSets.push_back(text(child(link, "TileMatrixSet")));
    for (const XMLElement* r : children(l, "ResourceURL")) {
      const char* type = r->Attribute("resourceType");
      const char* format = r->Attribute("format");
      const char* tmpl = r->Attribute("template");
      if (type != nullptr && std::strcmp(type, "tile") == 0 && tmpl != nullptr) {
        layer.tileTemplates.emplace(format != nullptr ? format : "", tmpl);
      }
    }
    if (const XMLElement* box = child(l, "WGS84BoundingBox")) {
      double w = 0, s = 0, e = 0, n = 0;
      if (twoNumbers(text(child(box, "LowerCorner")), w, s) &&
          twoNumbers(text(child(box, "UpperCorner")), e, n) && w < e && s < n) {
        layer.bounds = {std::max(w, -180.0), std::max(s, -90.0), std::min(e, 180.0),
                        std::min(n, 90.0)};
      }
    }
    if (!layer.identifier.empty()) caps.layers.push_back(std::move(layer));
  }
  return caps;
}

}  // namespace globe::services
