// globe: the virtual-globe viewer's command line. Subcommands wire the libraries together.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "apps/globe/camera_argument.hpp"
#include "apps/globe/info_command.hpp"
#include "apps/globe/play_command.hpp"
#include "apps/globe/query_command.hpp"
#include "apps/globe/snapshot_command.hpp"
#include "apps/globe/view_command.hpp"
#include "formats/layer_manifest.hpp"
#include "formats/pyramid_manifest.hpp"
#include "geo/ellipsoid.hpp"
#include "globe_version.hpp"
#include "terrain/height_block.hpp"
#include "transport/network_settings.hpp"

int main(int argc, char** argv) {
  CLI::App app{"globe: a virtual-globe terrain viewer with real-time camera-terrain collision",
               "globe"};
  app.set_version_flag(
      "--version", std::string("globe ") + globe::kVersion + " (" + globe::kSourceRevision + ")");
  app.require_subcommand(1);
  std::string globeName = "wgs84";
  auto addGlobe = [&](CLI::App* command) {
    command
        ->add_option("--globe", globeName,
                     "globe model: wgs84 (default) | sphere (the paper's, r = 6,371,000 m)")
        ->capture_default_str();
  };
  bool seaFloor = false;
  auto addSeaFloor = [&](CLI::App* command) {
    command->add_flag("--sea-floor", seaFloor,
                      "draw the sea floor (bathymetry) where the pyramid has it, and let the "
                      "camera go under water; default: the water surface at 0 m is the ground");
  };

  std::vector<std::string> layerTexts;
  bool lighting = false;
  bool nominalLod = false;
  bool noSky = false;
  auto addLayers = [&](CLI::App* command) {
    command->add_option("--layer", layerTexts,
                        "imagery layer directory made by `globe-tiler imagery`, optionally "
                        "DIR,OPACITY (0..1); repeat for more, bottom layer first");
    command->add_flag("--lighting", lighting,
                      "hill-shade the imagery too (off by default: imagery has its own shadows)");
    command->add_flag("--no-sky", noSky, "black space instead of the sky, and no distance fog");
    command->add_flag("--nominal-lod", nominalLod,
                      "refine by each level's nominal error, not the tiler's measured one (more "
                      "triangles where the ground is smooth; as before pack format 3)");
  };
  std::string cacheDir;
  bool offline = false;
  uint64_t cacheMegabytes = 2048;
  double httpTimeoutSeconds = 120;
  auto addNetwork = [&](CLI::App* command) {
    command->add_option("--cache-dir", cacheDir,
                        "disk cache of pyramids and layers read over http(s) (default: "
                        "$XDG_CACHE_HOME/globe, else ~/.cache/globe)");
    command->add_option("--cache-size-mb", cacheMegabytes, "the disk cache's bound (LRU)")
        ->capture_default_str()
        ->check(CLI::Range(uint64_t{16}, uint64_t{1} << 24));
    command->add_flag("--offline", offline,
                      "read http(s) pyramids and layers from the disk cache alone");
    command
        ->add_option("--http-timeout", httpTimeoutSeconds,
                     "seconds a request may take, and may go without data (a stalled server); "
                     "each is tried 3 times")
        ->capture_default_str()
        ->check(CLI::Range(1.0, 3600.0));
  };
  // --layer, --lighting, --no-sky and --nominal-lod into the scene options; false (after printing
  // why) on a bad --layer.
  auto applyLayers = [&](const char* command, globe::scene::SceneOptions& scene) {
    for (const std::string& text : layerTexts) {
      auto layer = globe::scene::parseLayerArgument(text);
      if (!layer) {
        std::fprintf(stderr, "globe %s: %s\n", command, layer.error().c_str());
        return false;
      }
      scene.layers.push_back(*layer);
    }
    scene.lightImagery = lighting;
    scene.measuredLod = !nominalLod;
    scene.sky = !noSky;
    return true;
  };

  CLI::App* info = app.add_subcommand(
      "info", "print a pyramid's (or an imagery layer's) levels, tile counts, bounds and sources");
  std::string pyramid;
  bool json = false;
  info->add_option("DIR", pyramid,
                   "pyramid or imagery layer made by globe-tiler: a directory or its http(s) URL")
      ->required();
  info->add_flag("--json", json, "machine-readable output");
  addGlobe(info);
  addNetwork(info);

  CLI::App* snapshot = app.add_subcommand(
      "snapshot", "render one view headless (OSMesa) once every tile it needs is loaded");
  std::string cameraText, sizeText = "1280x720", output, imagery;
  bool aboveTerrain = false;
  std::string sseText = "2";  // numbers as text: checked and named by parseNumberArgument
  uint32_t maxLoadLevel = globe::geo::kMaxLevel;
  snapshot
      ->add_option("PYRAMID", pyramid,
                   "pyramid made by globe-tiler: a directory or its http(s) URL")
      ->required();
  snapshot
      ->add_option("--camera", cameraText,
                   "LON,LAT,HEIGHT[,HEADING,PITCH,ROLL]: degrees, metres above the ellipsoid; "
                   "heading 0 = north, pitch -90 = straight down (default)")
      ->required();
  snapshot->add_option("--size", sizeText, "WxH pixels")->capture_default_str();
  snapshot->add_option("-o,--output", output, "PNG file to write")->required();
  snapshot->add_flag("--above-terrain", aboveTerrain,
                     "HEIGHT is above the terrain, not the ellipsoid");
  snapshot->add_option("--imagery", imagery, "equirectangular world image to drape (JPEG/PNG)");
  snapshot->add_option("--sse", sseText, "maximum screen-space error in pixels (0.1..10000)")
      ->capture_default_str();
  snapshot->add_option("--max-load-level", maxLoadLevel,
                       "never load tiles deeper than this (shows a view mid-refinement)");
  addGlobe(snapshot);
  addNetwork(snapshot);
  addSeaFloor(snapshot);
  addLayers(snapshot);

  CLI::App* query = app.add_subcommand(
      "query", "heights: reads lon,lat lines (degrees) on stdin, prints lon,lat,level,height_m");
  std::string mode = "qotcd";
  uint32_t queryLevel = 0;
  query
      ->add_option("PYRAMID", pyramid,
                   "pyramid made by globe-tiler: a directory or its http(s) URL")
      ->required();
  query
      ->add_option("--mode", mode,
                   "qotcd (the paper's conservative height) | exact (the drawn surface)")
      ->capture_default_str();
  auto* queryLevelOption =
      query->add_option("--level", queryLevel, "query this level (default: the finest there)");
  addGlobe(query);
  addNetwork(query);
  addSeaFloor(query);

  CLI::App* view = app.add_subcommand(
      "view",
      "open an interactive window: orbit (drag rotates, scroll zooms, double-click flies to a "
      "point) and fly (F/Tab; WASD/QE, drag looks, Shift x5); P records the path, K/F12 takes a "
      "screenshot, H shows every key, Esc quits");
  std::string viewCamera = "0,20,20000000", viewSize = "1280x720", viewImagery, viewScreenshot;
  std::string viewRecordDir;
  int viewFrames = 0;
  bool viewLog = false;
  view->add_option("PYRAMID", pyramid,
                   "pyramid made by globe-tiler: a directory or its http(s) URL")
      ->required();
  view->add_option("--camera", viewCamera, "LON,LAT,HEIGHT[,HEADING,PITCH,ROLL] to start from")
      ->capture_default_str();
  view->add_option("--size", viewSize, "WxH window size")->capture_default_str();
  view->add_option("--imagery", viewImagery, "equirectangular world image to drape (JPEG/PNG)");
  view->add_option("--frames", viewFrames, "redraw continuously and quit after N frames (tests)");
  view->add_option("--screenshot", viewScreenshot, "write the last frame to this PNG on exit");
  view->add_flag("--log", viewLog, "print when the view is complete, and the camera on exit");
  view->add_option("--record-dir", viewRecordDir,
                   "where P (globe-path-*.json) and K/F12 (globe-shot-*.png) write (default: .)");
  addGlobe(view);
  addNetwork(view);
  addSeaFloor(view);
  addLayers(view);

  CLI::App* play = app.add_subcommand(
      "play",
      "play a camera path (.json or KML tour) through the collision controller, headless "
      "(OSMesa): frames, log.csv, timing.csv, summary.txt in --out");
  std::string playPath, playOut, playSize = "1280x720", playVideo;
  std::string playFps = "30";
  bool playNoFrames = false, playWindow = false;
  play->add_option("PYRAMID", pyramid,
                   "pyramid made by globe-tiler: a directory or its http(s) URL")
      ->required();
  play->add_option("PATH", playPath, "camera path: .json keyframes or a .kml gx:Tour")->required();
  play->add_option("--out", playOut, "output directory")->required();
  play->add_option("--fps", playFps, "frames per second of path time (0..1000]")
      ->capture_default_str();
  play->add_option("--size", playSize, "WxH pixels")->capture_default_str();
  play->add_flag("--no-frames", playNoFrames, "write the logs only, no PNG frames");
  play->add_flag("--window", playWindow, "show the playback in a GLFW window (same loop)");
  play->add_option("--video", playVideo, "encode the frames into this MP4 with ffmpeg");
  addGlobe(play);
  addNetwork(play);
  addSeaFloor(play);
  addLayers(play);

  CLI11_PARSE(app, argc, argv);
  {
    globe::transport::NetworkSettings network;
    network.cacheDirectory = cacheDir;
    network.cacheBudgetBytes = cacheMegabytes << 20;
    network.remote.offline = offline;
    network.http.totalTimeoutMs = static_cast<long>(httpTimeoutSeconds * 1000);
    network.http.stallTimeoutMs =
        std::min(network.http.stallTimeoutMs, network.http.totalTimeoutMs);
    network.http.connectTimeoutMs =
        std::min(network.http.connectTimeoutMs, network.http.totalTimeoutMs);
    globe::transport::setNetworkSettings(network);
  }
  const auto globeModel = globe::geo::parseGlobeModel(globeName);
  if (!globeModel) {
    std::fprintf(stderr, "globe: --globe must be wgs84 or sphere, not '%s'\n", globeName.c_str());
    return 2;
  }
  const auto sea =
      seaFloor ? globe::terrain::SeaSurface::SeaFloor : globe::terrain::SeaSurface::Water;

  if (snapshot->parsed()) {
    auto pose = globe::app::parseCameraArgument(cameraText);
    auto size = globe::app::parseSizeArgument(sizeText);
    auto sse = globe::app::parseNumberArgument("--sse", sseText, 0.1, 10000);
    if (!pose || !size || !sse) {
      std::fprintf(stderr, "globe snapshot: %s\n",
                   (!pose   ? pose.error()
                    : !size ? size.error()
                            : sse.error())
                       .c_str());
      return 2;
    }
    globe::app::SnapshotOptions options;
    options.pyramid = pyramid;
    options.pose = *pose;
    options.heightAboveTerrain = aboveTerrain;
    options.widthPixels = size->first;
    options.heightPixels = size->second;
    options.output = output;
    if (!imagery.empty()) options.imagery = imagery;
    options.scene.globeModel = *globeModel;
    options.scene.maximumScreenSpaceErrorPixels = *sse;
    options.scene.maximumLoadLevel = maxLoadLevel;
    options.scene.sea = sea;
    if (!applyLayers("snapshot", options.scene)) return 2;
    auto report = globe::app::runSnapshot(options);
    if (!report) {
      std::fprintf(stderr, "globe snapshot: %s\n", report.error().c_str());
      return 1;
    }
    std::printf("%s: %u tiles drawn, %llu triangles, %llu tile loads, %.2f s\n", output.c_str(),
                report->tilesDrawn, static_cast<unsigned long long>(report->triangles),
                static_cast<unsigned long long>(report->tileLoads), report->seconds);
  }

  if (query->parsed()) {
    globe::app::QueryOptions options;
    options.pyramid = pyramid;
    options.globeModel = *globeModel;
    options.sea = sea;
    if (mode == "exact") {
      options.mode = globe::collision::HeightMode::Exact;
    } else if (mode != "qotcd") {
      std::fprintf(stderr, "globe query: --mode must be qotcd or exact, not '%s'\n", mode.c_str());
      return 2;
    }
    if (queryLevelOption->count() > 0) options.level = queryLevel;
    auto report = globe::app::runQuery(options, std::cin, stdout, stderr);
    if (!report) {
      std::fprintf(stderr, "globe query: %s\n", report.error().c_str());
      return 1;
    }
    return report->rejected > 0 ? 1 : 0;
  }

  if (view->parsed()) {
    auto pose = globe::app::parseCameraArgument(viewCamera);
    auto size = globe::app::parseSizeArgument(viewSize);
    if (!pose || !size) {
      std::fprintf(stderr, "globe view: %s\n", (!pose ? pose.error() : size.error()).c_str());
      return 2;
    }
    if (viewFrames < 0) {
      std::fprintf(stderr, "globe view: --frames %d: must be at least 0\n", viewFrames);
      return 2;
    }
    globe::app::ViewOptions options;
    options.pyramid = pyramid;
    options.pose = *pose;
    options.widthPixels = size->first;
    options.heightPixels = size->second;
    if (!viewImagery.empty()) options.imagery = viewImagery;
    if (!viewScreenshot.empty()) options.screenshot = viewScreenshot;
    options.frames = viewFrames;
    options.log = viewLog;
    options.recordDirectory = viewRecordDir;
    options.scene.globeModel = *globeModel;
    options.scene.sea = sea;
    if (!applyLayers("view", options.scene)) return 2;
    // A server that failed may come back: its tiles are asked for again every 10 s.
    bool remote = globe::transport::isHttpUrl(pyramid);
    for (const auto& layer : options.scene.layers)
      remote |= globe::transport::isHttpUrl(layer.directory);
    if (remote) options.scene.retryFailedLoadsSeconds = 10;
    if (auto report = globe::app::runView(options); !report) {
      std::fprintf(stderr, "globe view: %s\n", report.error().c_str());
      return 1;
    }
  }

  if (play->parsed()) {
    auto size = globe::app::parseSizeArgument(playSize);
    auto fps = globe::app::parseNumberArgument("--fps", playFps, 0, 1000, true);
    if (!size || !fps) {
      std::fprintf(stderr, "globe play: %s\n", (!size ? size.error() : fps.error()).c_str());
      return 2;
    }
    globe::app::PlayOptions options;
    options.pyramid = pyramid;
    options.pathFile = playPath;
    options.outputDir = playOut;
    options.framesPerSecond = *fps;
    options.widthPixels = size->first;
    options.heightPixels = size->second;
    options.writeFrames = !playNoFrames;
    options.window = playWindow;
    if (!playVideo.empty()) options.video = playVideo;
    options.scene.globeModel = *globeModel;
    options.scene.sea = sea;
    if (!applyLayers("play", options.scene)) return 2;
    auto report = globe::app::runPlay(options);
    if (!report) {
      std::fprintf(stderr, "globe play: %s\n", report.error().c_str());
      return 1;
    }
    std::fputs(report->summaryText.c_str(), stdout);
  }

  if (info->parsed()) {
    auto source = globe::transport::openByteSource(pyramid);
    if (!source) {
      std::fprintf(stderr, "globe info: %s\n", source.error().c_str());
      return 1;
    }
    auto asText = [](const std::vector<std::byte>& bytes) {
      return std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    };
    auto pyramidBytes = (*source)->readWhole(globe::formats::kManifestFileName,
                                             globe::formats::kMaxManifestFileBytes);
    if (!pyramidBytes) {
      std::fprintf(stderr, "globe info: %s\n", pyramidBytes.error().c_str());
      return 1;
    }
    if (!*pyramidBytes) {
      // An imagery layer (globe-tiler imagery) rather than a pyramid?
      auto layerBytes = (*source)->readWhole(globe::formats::kLayerManifestFileName,
                                             globe::formats::kMaxManifestFileBytes);
      if (!layerBytes) {
        std::fprintf(stderr, "globe info: %s\n", layerBytes.error().c_str());
        return 1;
      }
      if (*layerBytes) {
        auto layer = globe::formats::layerManifestFromJson(
            asText(**layerBytes), (*source)->locationOf(globe::formats::kLayerManifestFileName));
        if (!layer) {
          std::fprintf(stderr, "globe info: %s\n", layer.error().c_str());
          return 1;
        }
        const std::string out = json ? globe::formats::layerManifestToJson(*layer) + "\n"
                                     : globe::app::formatLayerInfoText(*layer, pyramid);
        std::fputs(out.c_str(), stdout);
        return 0;
      }
    }
    // The pyramid's manifest, or what is missing or wrong with it.
    auto manifest = *pyramidBytes ? globe::formats::manifestFromJson(
                                        asText(**pyramidBytes),
                                        (*source)->locationOf(globe::formats::kManifestFileName))
                                  : globe::formats::readManifest(**source);
    if (!manifest) {
      std::fprintf(stderr, "globe info: %s\n", manifest.error().c_str());
      return 1;
    }
    const std::string text = json ? globe::app::formatPyramidInfoJson(*manifest, pyramid)
                                  : globe::app::formatPyramidInfoText(*manifest, pyramid);
    std::fputs(text.c_str(), stdout);
  }
  return 0;
}
