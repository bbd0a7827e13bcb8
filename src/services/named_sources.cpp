#include "services/named_sources.hpp"

#include <toml++/toml.h>
#include <algorithm>
#include <cstdlib>

namespace globe::services {
namespace {

const char* kindName(SourceKind kind) {
  return kind == SourceKind::Terrain ? "terrain" : "imagery";
}

bool validName(const std::string& name) {
  return !name.empty() && name.size() <= 64 &&
         std::all_of(name.begin(), name.end(), [](unsigned char c) {
           return std::isalnum(c) || c == '-' || c == '_' || c == '.';
         });
}

}  // namespace

std::vector<NamedSource> presetSources() {
  std::vector<NamedSource> p;
  p.push_back({"aws-terrain", SourceKind::Terrain,
               "terrarium:https://s3.amazonaws.com/elevation-tiles-prod/terrarium/{z}/{x}/{y}.png"
               "?maxzoom=15",
               "Terrain Tiles (Mapzen, AWS): SRTM, GMTED, ETOPO1, 3DEP and others",
               "the open AWS Terrain Tiles (Mapzen's Terrarium), global, zooms 0-15; sources: "
               "github.com/tilezen/joerd/blob/master/docs/attribution.md",
               true});
  p.push_back(
      {"osm", SourceKind::Imagery, "xyz:https://tile.openstreetmap.org/{z}/{x}/{y}.png?maxzoom=19",
       "© OpenStreetMap contributors",
       "OpenStreetMap's standard tiles; its tile usage policy applies (operations.osmfoundation"
       ".org/policies/tiles): viewing only, no bulk downloads, cached on disk",
       true});
  p.push_back({"gibs", SourceKind::Imagery,
               "wmts:https://gibs.earthdata.nasa.gov/wmts/epsg4326/best/1.0.0/WMTSCapabilities.xml"
               "?layer=BlueMarble_ShadedRelief_Bathymetry",
               "NASA EOSDIS GIBS",
               "NASA GIBS WMTS, Blue Marble with shaded relief and bathymetry (other layers: "
               "wmts:...WMTSCapabilities.xml?layer=NAME)",
               true});
  p.push_back(
      {"s2cloudless", SourceKind::Imagery,
       "xyz:https://tiles.maps.eox.at/wmts/1.0.0/s2cloudless-2020_3857/default/g/{z}/{y}/{x}"
       ".jpg?maxzoom=17",
       "Sentinel-2 cloudless - https://s2maps.eu by EOX IT Services GmbH (Contains modified "
       "Copernicus Sentinel data 2020)",
       "EOX Sentinel-2 cloudless 2020, 10 m imagery of the whole Earth (CC BY-NC-SA 4.0: "
       "non-commercial use)",
       true});
  return p;
}

std::filesystem::path userSourcesFile() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg != nullptr && xdg[0] == '/') {
    return std::filesystem::path(xdg) / "globe" / "sources.toml";
  }
  const char* home = std::getenv("HOME");
  return std::filesystem::path(home != nullptr ? home : ".") / ".config" / "globe" / "sources.toml";
}

Result<NamedSources> loadNamedSources(const std::filesystem::path& file) {
  NamedSources out;
  out.sources = presetSources();
  out.file = file;
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return out;
  toml::table table;
  try {
    table = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    return makeError(file.string() + ":" + std::to_string(e.source().begin.line) + ": " +
                     std::string(e.description()));
  }
  out.fileRead = true;
  for (const auto& [key, node] : table) {
    const std::string name(key.str());
    const std::string where = file.string() + ": [" + name + "]";
    const toml::table* entry = node.as_table();
    if (entry == nullptr) return makeError(where + " is not a table");
    if (!validName(name)) {
      return makeError(where + ": a name is letters, digits, '-', '_' and '.' (at most 64)");
    }
    NamedSource source;
    source.name = name;
    const std::string kind = entry->get_as<std::string>("kind") != nullptr
                                 ? entry->get_as<std::string>("kind")->get()
                                 : "";
    if (kind == "terrain") {
      source.kind = SourceKind::Terrain;
    } else if (kind == "imagery") {
      source.kind = SourceKind::Imagery;
    } else {
      return makeError(where + ": kind must be \"terrain\" or \"imagery\"");
    }
    const auto* url = entry->get_as<std::string>("url");
    if (url == nullptr || url->get().empty()) return makeError(where + ": no url");
    source.url = url->get();
    if (const auto* a = entry->get_as<std::string>("attribution")) source.attribution = a->get();
    if (const auto* d = entry->get_as<std::string>("description")) source.description = d->get();
    auto same = std::find_if(out.sources.begin(), out.sources.end(),
                             [&](const NamedSource& s) { return s.name == name; });
    if (same != out.sources.end()) {
      *same = source;  // the user's replaces the preset
    } else {
      out.sources.push_back(source);
    }
  }
  return out;
}

Result<std::optional<NamedSource>> findNamedSource(const NamedSources& sources,
                                                   const std::string& text, SourceKind kind) {
  for (const NamedSource& s : sources.sources) {
    if (s.name != text) continue;
    if (s.kind != kind) {
      return makeError(text + (s.kind == SourceKind::Imagery ? " is an " : " is a ") +
                       std::string(kindName(s.kind)) + " source, not " +
                       (kind == SourceKind::Terrain ? "terrain" : "imagery") +
                       (s.kind == SourceKind::Imagery ? " (give it with --layer)"
                                                      : " (give it as the PYRAMID argument)"));
    }
    return std::optional<NamedSource>(s);
  }
  return std::optional<NamedSource>();
}

}  // namespace globe::services
