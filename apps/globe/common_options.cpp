#include "apps/globe/common_options.hpp"
#include "apps/globe/layer_argument.hpp"
#include "apps/globe/stderr_warnings.hpp"
#include "apps/globe/tileset_options.hpp"
#include "apps/globe/wrong_kind_hint.hpp"
#include "overlays/overlay_file.hpp"
#include "services/imagery_services.hpp"
#include "services/terrain_services.hpp"
#include "services/url_template.hpp"
#include "sun/utc_time.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <optional>
#include <tuple>

namespace globe::app {

Result<std::string> resolveSourceName(const CommonArguments& arguments, const std::string& text,
                                      services::SourceKind kind) {
  std::error_code ec;
  // A directory of that name wins over a source's.
  if (!arguments.sources || std::filesystem::exists(text, ec)) return text;
  auto found = services::findNamedSource(*arguments.sources, text, kind);
  if (!found) return Error{found.error()};
  if (!*found) return text;
  std::string url = (*found)->url;
  const bool service = services::isTerrainService(url) || services::isImageryService(url);
  if (service && !(*found)->attribution.empty() && url.find("attribution=") == std::string::npos) {
    url += (url.find('?') == std::string::npos ? "?" : "&") + std::string("attribution=") +
           services::percentEncode((*found)->attribution);
  }
  return url;
}

void addPyramidArgument(CLI::App& command, std::string& pyramid, const CommonArguments& common) {
  command
      .add_option("PYRAMID", pyramid,
                  "pyramid made by globe-tiler (a directory or its http(s) URL), or a terrain "
                  "service: quantized-mesh:URL (Cesium terrain, layer.json or its folder), "
                  "terrarium:TEMPLATE or terrain-rgb:TEMPLATE ({z}/{x}/{y} PNG tiles), or a "
                  "source's name (globe sources)")
      ->required()
      ->transform(CLI::Validator(
          [&common](std::string& text) -> std::string {
            auto resolved = resolveSourceName(common, text, services::SourceKind::Terrain);
            if (!resolved) return resolved.error();
            text = *resolved;
            return {};
          },
          "", "named source"));
}

void addImageryOption(CLI::App& command, std::string& image) {
  command.add_option("--imagery", image, "equirectangular world image to drape (JPEG/PNG)");
}

void addGlobeOption(CLI::App& command, CommonArguments& arguments) {
  command
      .add_option("--globe", arguments.globeName,
                  "globe model: wgs84 (default) | sphere (the paper's, r = 6,371,000 m)")
      ->capture_default_str();
}

void addNetworkOptions(CLI::App& command, CommonArguments& arguments) {
  command.add_option("--cache-dir", arguments.cacheDirectory,
                     "disk cache of pyramids and layers read over http(s) (default: "
                     "$XDG_CACHE_HOME/globe, else ~/.cache/globe)");
  command.add_option("--cache-size-mb", arguments.cacheMegabytes, "the disk cache's bound (LRU)")
      ->capture_default_str()
      ->check(CLI::Range(uint64_t{16}, uint64_t{1} << 24));
  command.add_flag("--offline", arguments.offline,
                   "read http(s) pyramids and layers from the disk cache alone");
  command
      .add_option("--http-timeout", arguments.httpTimeoutSeconds,
                  "seconds a request may take in all (a server that stalls for 8 s, or for "
                  "this long when shorter, fails sooner); tried 3 times, a timeout twice")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 3600.0));
}

void addSeaFloorOption(CLI::App& command, CommonArguments& arguments) {
  command.add_flag("--sea-floor", arguments.seaFloor,
                   "draw the sea floor (bathymetry) where the pyramid has it, and let the "
                   "camera go under water; default: the water surface at 0 m is the ground");
}

void addLayerOptions(CLI::App& command, CommonArguments& arguments) {
  command.add_option("--layer", arguments.layerTexts,
                     "imagery layer directory made by `globe-tiler imagery`, a service "
                     "(xyz:TEMPLATE, tms:URL, wmts:URL?layer=NAME, pmtiles:URL) or a source's "
                     "name (globe sources), optionally LAYER,OPACITY (0..1); repeat for more, "
                     "bottom layer first. A water mask made "
                     "by `globe-tiler water-mask` (at most one) decides land and water where the "
                     "terrain is coarser; its opacity scales that");
  command.add_option("--night-layer", arguments.nightLayerTexts,
                     "a night-lights layer (a city-lights image, as --layer): shown only where "
                     "the Sun has set under --time, as light of its own; counts among the 4 "
                     "layers");
  command
      .add_option("--exposure", arguments.exposure,
                  "imagery exposure: auto (a dark layer, its median luminance under 0.3, lifted "
                  "by 1 - (1 - c)^k, k up to 3), off, or k (>= 1) for every layer")
      ->type_name("auto|off|K");  // checked in applySceneArguments: a bad value exits 2
  command
      .add_option("--overlay", arguments.overlayFiles,
                  "KML, KMZ, GeoJSON or GPX file to show over the terrain: lines and "
                  "polygons draped on the ground, placemarks with their icons and labels, "
                  "ground overlays; repeat for more")
      ->type_name("FILE");
  addTilesetOptions(command, arguments);
  command.add_flag("--overlay-hidden", arguments.overlayHidden,
                   "also draw what the overlay files hide (KML visibility 0), as if every item "
                   "were ticked");
  // A bare --lighting (before layers could be lit by resolution: the only way to light them)
  // still means on.
  command
      .add_option("--lighting", arguments.lighting,
                  "hill-shading on imagery: auto (full where its texels are coarser than the "
                  "terrain's samples, gentle where they carry their own shadows), on (full), off "
                  "(the imagery's own shading only); a bare --lighting is on")
      ->expected(0, 1)
      ->type_name("[auto|on|off]");  // checked in applySceneArguments: a bad value exits 2
  command.add_flag("--no-sky", arguments.noSky,
                   "black space instead of the sky, and no distance fog");
  command
      .add_option("--samples", arguments.samples,
                  "anti-aliasing: samples a pixel (1 = off; at most what the GL offers, 8 on "
                  "llvmpipe): smooth silhouettes, coasts and lines")
      ->check(CLI::Range(1, 32))
      ->capture_default_str();
  command.add_flag("--no-shadows", arguments.noShadows,
                   "with --time: no terrain shadows (they are computed on the CPU, ~5 ms a tile "
                   "at a low Sun)");
  command
      .add_option("--time", arguments.time,
                  "light the terrain by the real Sun at this instant, ISO-8601 with its zone "
                  "(2024-06-21T06:30:00Z, 2024-06-21T08:30+02:00): slopes facing the Sun "
                  "bright, the night side dark (`globe sun` says where the Sun stands); "
                  "without it a light from the north-west follows the camera")
      ->type_name("ISO-8601");
  command.add_flag("--nominal-lod", arguments.nominalLod,
                   "refine by each level's nominal error, not the tiler's measured one (more "
                   "triangles where the ground is smooth; as before pack format 3)");
}

std::optional<CommandContext> makeCommandContext(const CommonArguments& arguments) {
  const auto globeModel = geo::parseGlobeModel(arguments.globeName);
  if (!globeModel) {
    std::fprintf(stderr, "globe: --globe must be wgs84 or sphere, not '%s'\n",
                 arguments.globeName.c_str());
    return std::nullopt;
  }
  CommandContext context;
  context.globeModel = *globeModel;
  context.sea = arguments.seaFloor ? terrain::SeaSurface::SeaFloor : terrain::SeaSurface::Water;
  context.warnings = stderrWarnings();
  transport::NetworkSettings network;
  network.cacheDirectory = arguments.cacheDirectory;
  network.cacheBudgetBytes = arguments.cacheMegabytes << 20;
  network.remote.offline = arguments.offline;
  network.http.totalTimeoutMs = static_cast<long>(arguments.httpTimeoutSeconds * 1000);
  network.http.stallTimeoutMs = std::min(network.http.stallTimeoutMs, network.http.totalTimeoutMs);
  network.http.connectTimeoutMs =
      std::min(network.http.connectTimeoutMs, network.http.totalTimeoutMs);
  context.network = std::make_shared<transport::Network>(network, context.warnings);
  return context;
}

namespace {

// --layer's or --night-layer's LAYER[,OPACITY], a named source resolved; said and nullopt if
// it is not a layer.
std::optional<scene::LayerOptions> layerArgument(const char* command, const char* option,
                                                 const CommonArguments& arguments,
                                                 const std::string& given) {
  // A named source, with or without ",OPACITY".
  std::string text = given;
  const size_t comma = given.rfind(',');
  for (const std::string& name :
       {given, comma == std::string::npos ? std::string() : given.substr(0, comma)}) {
    if (name.empty()) continue;
    auto resolved = resolveSourceName(arguments, name, services::SourceKind::Imagery);
    if (!resolved) {
      std::fprintf(stderr, "globe %s: %s %s\n", command, option, resolved.error().c_str());
      return std::nullopt;
    }
    if (*resolved != name) {
      text = *resolved + given.substr(name.size());
      break;
    }
  }
  auto layer = parseLayerArgument(text);
  if (!layer) {
    std::fprintf(stderr, "globe %s: %s\n", command, layer.error().c_str());
    return std::nullopt;
  }
  if (const std::string hint = layerGivenAnOverlayHint(layer->directory); !hint.empty()) {
    std::fprintf(stderr, "globe %s: %s %s: not a layer%s\n", command, option, given.c_str(),
                 hint.c_str());
    return std::nullopt;
  }
  return *layer;
}

// --exposure: auto → NaN (chosen per layer), off → 1, a number >= 1 as it is.
std::optional<float> parseExposure(const std::string& text) {
  if (text == "auto") return std::numeric_limits<float>::quiet_NaN();
  if (text == "off") return 1.0f;
  char* end = nullptr;
  const float value = std::strtof(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !(value >= 1.0f) || !(value <= 16.0f)) {
    return std::nullopt;
  }
  return value;
}

}  // namespace

bool applySceneArguments(const char* command, const CommonArguments& arguments,
                         const CommandContext& context, scene::SceneOptions& scene) {
  scene.globeModel = context.globeModel;
  scene.sea = context.sea;
  scene.network = context.network;
  scene.warnings = context.warnings;
  const auto exposure = parseExposure(arguments.exposure);
  if (!exposure) {
    std::fprintf(stderr, "globe %s: --exposure must be auto, off or a number >= 1, not '%s'\n",
                 command, arguments.exposure.c_str());
    return false;
  }
  for (const auto& [texts, option, night] :
       {std::tuple{&arguments.layerTexts, "--layer", false},
        std::tuple{&arguments.nightLayerTexts, "--night-layer", true}}) {
    for (const std::string& given : *texts) {
      auto layer = layerArgument(command, option, arguments, given);
      if (!layer) return false;
      layer->night = night;
      layer->exposure = *exposure;
      scene.layers.push_back(*layer);
    }
  }
  for (const std::string& file : arguments.overlayFiles) {
    auto document = overlays::readOverlayFile(file);
    if (!document) {
      std::fprintf(stderr, "globe %s: --overlay %s%s\n", command, document.error().c_str(),
                   overlayGivenALayerHint(file).c_str());
      return false;
    }
    for (const std::string& warning : document->warnings) {
      std::fprintf(stderr, "globe %s: warning: %s\n", command, warning.c_str());
    }
    if (arguments.overlayHidden) overlays::showEverything(*document);
    scene.overlays.push_back(
        std::make_shared<const overlays::OverlayDocument>(std::move(*document)));
  }
  if (!applyTilesetArguments(command, arguments, scene)) return false;
  // A bare --lighting parses as "".
  const auto lighting = arguments.lighting.empty()
                            ? terrain::ImageryLighting::On
                            : terrain::parseImageryLighting(arguments.lighting);
  if (!lighting) {
    std::fprintf(stderr, "globe %s: --lighting must be auto, on or off, not '%s'\n", command,
                 arguments.lighting.c_str());
    return false;
  }
  scene.imageryLighting = *lighting;
  scene.measuredLod = !arguments.nominalLod;
  scene.sky = !arguments.noSky;
  scene.samples = arguments.samples;
  scene.shadows = !arguments.noShadows;
  if (!arguments.time.empty()) {
    auto time = sun::parseUtcTime(arguments.time);
    if (!time) {
      std::fprintf(stderr, "globe %s: --%s\n", command, time.error().c_str());
      return false;
    }
    scene.sunTimeUnixSeconds = *time;
  }
  return true;
}

}  // namespace globe::app
