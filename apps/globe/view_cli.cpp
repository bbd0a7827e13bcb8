// `globe view PYRAMID`: its options, and their conversion into ViewOptions.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/globe/camera_argument.hpp"
#include "apps/globe/go_to.hpp"
#include "apps/globe/subcommands.hpp"
#include "apps/globe/view_command.hpp"

namespace globe::app {
namespace {

struct ViewArguments {
  std::string pyramid;
  std::string camera = "0,20,20000000";
  std::string size = "1280x720";
  std::string imagery;
  std::string screenshot;
  std::string recordDirectory;
  int frames = 0;
  bool log = false;
  std::string goTo;
  std::string view;
};

int runViewCommand(const ViewArguments& arguments, const CommonArguments& common,
                   const CommandContext& context) {
  auto pose = parseCameraArgument(arguments.camera);
  auto size = parseSizeArgument(arguments.size);
  if (!pose || !size) {
    std::fprintf(stderr, "globe view: %s\n", (!pose ? pose.error() : size.error()).c_str());
    return 2;
  }
  if (arguments.frames < 0) {
    std::fprintf(stderr, "globe view: --frames %d: must be at least 0\n", arguments.frames);
    return 2;
  }
  ViewOptions options;
  options.pyramid = arguments.pyramid;
  options.pose = *pose;
  options.widthPixels = size->first;
  options.heightPixels = size->second;
  if (!arguments.imagery.empty()) options.imagery = arguments.imagery;
  if (!arguments.screenshot.empty()) options.screenshot = arguments.screenshot;
  options.frames = arguments.frames;
  options.log = arguments.log;
  options.recordDirectory = arguments.recordDirectory;
  if (!arguments.view.empty()) {
    auto view = savedViewNamed(arguments.view);
    if (!view) {
      std::fprintf(stderr, "globe view: %s\n", view.error().c_str());
      return 2;
    }
    options.pose = view->pose;
    options.heightAboveTerrain = view->heightAboveTerrain;
  }
  if (!arguments.goTo.empty()) {
    if (auto target = parseGoTo(arguments.goTo); !target) {
      std::fprintf(stderr, "globe view: %s\n", target.error().c_str());
      return 2;
    }
    options.goTo = arguments.goTo;
  }
  if (!applySceneArguments("view", common, context, options.scene)) return 2;
  // A server that failed may come back: its tiles are asked for again every 10 s.
  bool remote = transport::isHttpUrl(arguments.pyramid);
  for (const auto& layer : options.scene.layers) remote |= transport::isHttpUrl(layer.directory);
  if (remote) options.scene.retryFailedLoadsSeconds = 10;
  // Tiles arrive while the window draws: a finer tile near the camera rises over 8 frames.
  options.scene.morphFrames = 8;
  options.scene.shadowTilesPerFrame = 4;  // ~5 ms a tile at a low Sun: shadows fill in over frames
  if (auto report = runView(options); !report) {
    std::fprintf(stderr, "globe view: %s\n", report.error().c_str());
    return 1;
  }
  return 0;
}

}  // namespace

Subcommand addViewCommand(CLI::App& app, CommonArguments& common) {
  CLI::App* view = app.add_subcommand(
      "view",
      "open an interactive window: orbit (drag rotates, scroll zooms, double-click flies to a "
      "point) and fly (F/Tab; WASD/QE, drag looks, Shift x5); P records the path, K/F12 takes a "
      "screenshot, H shows every key, Esc quits");
  auto arguments = std::make_shared<ViewArguments>();
  addPyramidArgument(*view, arguments->pyramid, common);
  view->add_option("--camera", arguments->camera,
                   "LON,LAT,HEIGHT[,HEADING,PITCH,ROLL] to start from")
      ->capture_default_str();
  view->add_option("--size", arguments->size, "WxH window size")->capture_default_str();
  view->add_option("--go-to", arguments->goTo,
                   "fly to a place's name (globe search) or a position as the window opens");
  view->add_option("--view", arguments->view,
                   "start from a view saved by name (V in the window, globe views)")
      ->excludes("--camera");
  addImageryOption(*view, arguments->imagery);
  view->add_option("--frames", arguments->frames,
                   "redraw continuously and quit after N frames (tests)");
  view->add_option("--screenshot", arguments->screenshot,
                   "write the last frame to this PNG on exit");
  view->add_flag("--log", arguments->log,
                 "print when the view is complete, when it goes idle (all asked is on screen) "
                 "and the camera on exit");
  view->add_option("--record-dir", arguments->recordDirectory,
                   "where P (globe-path-*.json) and K/F12 (globe-shot-*.png) write (default: .)");
  addGlobeOption(*view, common);
  addNetworkOptions(*view, common);
  addSeaFloorOption(*view, common);
  addLayerOptions(*view, common);
  return {view, [arguments, &common](const CommandContext& context) {
            return runViewCommand(*arguments, common, context);
          }};
}

}  // namespace globe::app
