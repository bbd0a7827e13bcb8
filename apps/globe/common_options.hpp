// The options several `globe` subcommands share, each declared here once: the PYRAMID argument,
// --globe, the network's (--cache-dir, --cache-size-mb, --offline, --http-timeout), --sea-floor,
// --imagery and the imagery layers' (--layer, --lighting, --no-sky, --nominal-lod); and what they
// become once parsed: the globe model, the sea surface, the program's transport::Network and
// scene options.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/warnings.hpp"
#include "geo/ellipsoid.hpp"
#include "scene/terrain_scene.hpp"
#include "services/named_sources.hpp"
#include "terrain/height_block.hpp"
#include "transport/network_settings.hpp"

namespace globe::app {

// The shared options' values as parsed. One instance serves every subcommand (only one runs).
struct CommonArguments {
  std::string globeName = "wgs84";
  bool seaFloor = false;
  std::vector<std::string> layerTexts;
  std::vector<std::string> nightLayerTexts;  // --night-layer
  std::string exposure = "auto";             // --exposure auto | off | K
  std::vector<std::string> overlayFiles;     // --overlay
  std::vector<std::string> tilesets;         // --tileset
  std::string tilesetAt;                     // --tileset-at LON,LAT,H[,SCALE]
  bool tilesetClamp = false;                 // --tileset-clamp
  double tilesetErrorPixels = 16;            // --tileset-error
  bool overlayHidden = false;                // --overlay-hidden
  std::string lighting = "auto";             // --lighting auto | on | off; bare: on
  bool nominalLod = false;
  bool noSky = false;
  int samples = scene::kDefaultSamples;  // --samples
  bool noShadows = false;                // --no-shadows
  std::string time;  // --time: ISO-8601; empty: the light that follows the camera
  std::string cacheDirectory;
  bool offline = false;
  uint64_t cacheMegabytes = 2048;
  double httpTimeoutSeconds = 30;
  // The presets and the user's sources.toml (read by main before the arguments): names given
  // where a pyramid or a layer is are replaced by their URLs.
  std::shared_ptr<const services::NamedSources> sources;
};

// Each adds its options to `command`, stored in `arguments` (or `value`).
// PYRAMID: a directory, a URL, a terrain service, or a named terrain source.
void addPyramidArgument(CLI::App& command, std::string& pyramid, const CommonArguments& common);
// What `text` means as terrain or imagery: a named source's URL (with its attribution), else
// `text` as it is; an error for a source of the other kind.
Result<std::string> resolveSourceName(const CommonArguments& arguments, const std::string& text,
                                      services::SourceKind kind);
void addImageryOption(CLI::App& command, std::string& image);
void addGlobeOption(CLI::App& command, CommonArguments& arguments);
void addNetworkOptions(CLI::App& command, CommonArguments& arguments);
void addSeaFloorOption(CLI::App& command, CommonArguments& arguments);
// --layer, --overlay, --lighting, --no-sky, --time and --nominal-lod.
void addLayerOptions(CLI::App& command, CommonArguments& arguments);

// What the chosen subcommand runs with, made from the shared options once they are parsed.
struct CommandContext {
  geo::GlobeModel globeModel = geo::GlobeModel::Wgs84;
  terrain::SeaSurface sea = terrain::SeaSurface::Water;
  // The program's one network (--cache-dir, --cache-size-mb, --offline, --http-timeout): every
  // pyramid and layer given as an http(s) URL is read through it.
  std::shared_ptr<transport::Network> network;
  // Prints each library warning on stderr as "globe: WARNING".
  core::WarningSink warnings;
};

// nullopt (after printing why) on a bad --globe.
std::optional<CommandContext> makeCommandContext(const CommonArguments& arguments);

// The context's globe, sea, network and warnings and the layer options (--layer, --lighting,
// --no-sky, --time, --nominal-lod) into `scene`; false (after printing "globe COMMAND: why") on a
// bad --layer or --time.
bool applySceneArguments(const char* command, const CommonArguments& arguments,
                         const CommandContext& context, scene::SceneOptions& scene);

}  // namespace globe::app
