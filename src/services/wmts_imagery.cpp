#include "services/wmts_imagery.hpp"

#include <algorithm>
#include <cctype>
#include <iterator>

#include "services/template_imagery.hpp"
#include "services/url_reader.hpp"
#include "services/url_template.hpp"
#include "services/wmts_capabilities.hpp"

namespace globe::services {
namespace {

constexpr size_t kMaxCapabilitiesBytes = size_t{32} << 20;

// Replaces {Name} case-insensitively, as WMTS's templates are written either way.
std::string replaceKey(std::string s, const std::string& key, const std::string& value) {
  auto lower = [](std::string t) {
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
    return t;
  };
  const std::string needle = lower("{" + key + "}");
  for (size_t at = lower(s).find(needle); at != std::string::npos; at = lower(s).find(needle))
    s.replace(at, needle.size(), value);
  return s;
}

// PNG, JPEG or WebP, parameters and case aside: servers write "image/png; mode=8bit" (MapServer,
// for 8-bit palettes) or "image/jpg", and what arrives is decoded by its bytes in any case.
bool isDecodableImageFormat(const std::string& format) {
  std::string type = format.substr(0, format.find(';'));
  type.erase(std::remove(type.begin(), type.end(), ' '), type.end());
  std::transform(type.begin(), type.end(), type.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  static constexpr const char* kTypes[] = {"image/png", "image/jpeg", "image/jpg", "image/webp",
                                           "image/avif"};
  return std::find(std::begin(kTypes), std::end(kTypes), type) != std::end(kTypes);
}

std::string joinNames(const std::vector<std::string>& names, size_t most) {
  std::string out;
  for (size_t i = 0; i < names.size() && i < most; ++i) out += (i ? ", " : "") + names[i];
  if (names.size() > most) out += ", ... (" + std::to_string(names.size()) + " in all)";
  return out;
}

}  // namespace

Result<std::unique_ptr<ServiceImagery>> openWmtsImagery(
    const std::string& spec, std::shared_ptr<transport::Network> network) {
  std::string url = spec;
  auto options =
      takeQueryOptions(url, {"layer", "tilematrixset", "style", "format", "time", "attribution"});
  auto problem = [&](const std::string& what) { return makeError("wmts:" + spec + ": " + what); };
  auto reader = std::make_unique<UrlReader>(network, kImageAccept);
  auto bytes = reader->read(url, kMaxCapabilitiesBytes);
  if (!bytes) return Error{bytes.error()};
  if (!*bytes) return makeError(url + ": not found (the WMTS GetCapabilities document)");
  auto caps = parseWmtsCapabilities(
      std::string_view(reinterpret_cast<const char*>((*bytes)->data()), (*bytes)->size()), url);
  if (!caps) return Error{caps.error()};
  std::vector<std::string> names;
  for (const WmtsLayer& l : caps->layers) names.push_back(l.identifier);
  if (!options.count("layer")) {
    return problem("name a layer with ?layer=NAME; it has " + joinNames(names, 12));
  }
  const auto layer =
      std::find_if(caps->layers.begin(), caps->layers.end(),
                   [&](const WmtsLayer& l) { return l.identifier == options["layer"]; });
  if (layer == caps->layers.end()) {
    return problem("no layer " + options["layer"] + "; it has " + joinNames(names, 12));
  }
  // The tile matrix set: as asked, else the layer's first one this viewer can map.
  std::string setId;
  for (const std::string& id : layer->tileMatrixSets) {
    if (options.count("tilematrixset") ? id == options["tilematrixset"]
                                       : caps->tileMatrixSets.count(id) > 0) {
      setId = id;
      break;
    }
  }
  if (setId.empty() || !caps->tileMatrixSets.count(setId)) {
    return problem("no tile matrix set " +
                   (options.count("tilematrixset") ? options["tilematrixset"] + " " : "") +
                   "in Web Mercator or longitude/latitude for layer " + layer->identifier +
                   " (it links " + joinNames(layer->tileMatrixSets, 8) + ")");
  }
  const std::string style = options.count("style")  ? options["style"]
                            : layer->styles.empty() ? "default"
                                                    : layer->styles.front();
  std::string format = options.count("format") ? options["format"] : "";
  if (format.empty()) {
    for (const std::string& f : layer->formats)
      if (isDecodableImageFormat(f)) {
        format = f;
        break;
      }
  }
  if (format.empty()) return problem("none of its formats is PNG, JPEG, WebP or AVIF");
  const TileMatrixSet tiling = caps->tileMatrixSets.at(setId);
  std::string restful;
  if (auto t = layer->tileTemplates.find(format); t != layer->tileTemplates.end()) {
    restful = t->second;
  } else if (!layer->tileTemplates.empty() && caps->kvpGetTileUrl.empty()) {
    restful = layer->tileTemplates.begin()->second;
  }
  if (restful.empty() && caps->kvpGetTileUrl.empty()) {
    return problem("the server offers neither a RESTful tile template nor KVP GetTile");
  }
  // A time dimension (NASA GIBS's {Time}): as asked, else the server's default.
  restful = replaceKey(replaceKey(replaceKey(restful, "TileMatrixSet", setId), "Style", style),
                       "Time", options.count("time") ? options["time"] : "default");
  std::string kvp = resolveUrl(url, caps->kvpGetTileUrl);
  if (!kvp.empty() && kvp.back() != '?' && kvp.back() != '&') {
    kvp += kvp.find('?') == std::string::npos ? "?" : "&";
  }
  kvp += "SERVICE=WMTS&REQUEST=GetTile&VERSION=1.0.0&LAYER=" + percentEncode(layer->identifier) +
         "&STYLE=" + percentEncode(style) + "&TILEMATRIXSET=" + percentEncode(setId) +
         "&FORMAT=" + percentEncode(format);
  ImageryServiceDescription d;
  d.location = "wmts:" + spec;
  d.driver = "WMTS";
  d.tiling = tiling;
  d.bounds = layer->bounds;
  if (tiling.crs == TileCrs::WebMercator) {
    d.bounds.south = std::max(d.bounds.south, -kWebMercatorMaxLatitudeDegrees);
    d.bounds.north = std::min(d.bounds.north, kWebMercatorMaxLatitudeDegrees);
  }
  d.attribution = options.count("attribution") ? options["attribution"] : caps->title;
  d.remote = reader->remote(url);
  const std::string base = url;
  return makeUrlImagery(
      std::move(d), std::move(reader),
      [restful, kvp, tiling, base](size_t m, uint64_t column, uint64_t row) {
        const std::string& matrix = tiling.matrices[m].id;
        if (!restful.empty()) {
          return resolveUrl(base, replaceKey(replaceKey(replaceKey(restful, "TileMatrix", matrix),
                                                        "TileRow", std::to_string(row)),
                                             "TileCol", std::to_string(column)));
        }
        return kvp + "&TILEMATRIX=" + percentEncode(matrix) + "&TILEROW=" + std::to_string(row) +
               "&TILECOL=" + std::to_string(column);
      });
}

}  // namespace globe::services
