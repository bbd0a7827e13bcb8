// `globe snapshot PYRAMID --camera ... -o PNG`: its options, their conversion into
// SnapshotOptions, and what it prints.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/globe/camera_argument.hpp"
#include "apps/globe/go_to.hpp"
#include "apps/globe/snapshot_command.hpp"
#include "apps/globe/subcommands.hpp"

namespace globe::app {
namespace {

struct SnapshotArguments {
  std::string pyramid;
  std::string camera;
  std::string size = "1280x720";
  std::string output;
  std::string imagery;
  bool aboveTerrain = false;
  std::string sse = "2";  // numbers as text: checked and named by parseNumberArgument
  uint32_t maxLoadLevel = geo::kMaxLevel;
  bool noAttribution = false;
  bool allowMissing = false;
  bool verbose = false;
  int timeoutSeconds = SnapshotOptions{}.timeoutSeconds;
  std::string goTo;
  std::string view;
  CLI::Option* cameraOption = nullptr;  // count() > 0: --camera was given (even empty)
};

int runSnapshotCommand(const SnapshotArguments& arguments, const CommonArguments& common,
                       const CommandContext& context) {
  const bool camera = arguments.cameraOption != nullptr && arguments.cameraOption->count() > 0;
  if (int{camera} + int{!arguments.goTo.empty()} + int{!arguments.view.empty()} != 1) {
    std::fprintf(stderr, "globe snapshot: give --camera, --go-to or --view (one of them)\n");
    return 2;
  }
  Result<camera::CameraPose> pose = makeError("");
  bool aboveTerrain = arguments.aboveTerrain;
  if (!arguments.view.empty()) {
    auto view = savedViewNamed(arguments.view);
    if (!view) {
      std::fprintf(stderr, "globe snapshot: %s\n", view.error().c_str());
      return 2;
    }
    pose = view->pose;
    aboveTerrain = view->heightAboveTerrain;
  } else if (!arguments.goTo.empty()) {
    auto target = parseGoTo(arguments.goTo);
    if (!target) {
      std::fprintf(stderr, "globe snapshot: %s\n", target.error().c_str());
      return 2;
    }
    pose = goToPose(*target);
    aboveTerrain = true;
  } else {
    pose = parseCameraArgument(arguments.camera);
  }
  auto size = parseSizeArgument(arguments.size);
  auto sse = parseNumberArgument("--sse", arguments.sse, 0.1, 10000);
  if (!pose || !size || !sse) {
    std::fprintf(stderr, "globe snapshot: %s\n",
                 (!pose   ? pose.error()
                  : !size ? size.error()
                          : sse.error())
                     .c_str());
    return 2;
  }
  SnapshotOptions options;
  options.pyramid = arguments.pyramid;
  options.pose = *pose;
  options.heightAboveTerrain = aboveTerrain;
  options.widthPixels = size->first;
  options.heightPixels = size->second;
  options.output = arguments.output;
  options.attribution = !arguments.noAttribution;
  options.timeoutSeconds = arguments.timeoutSeconds;
  if (!arguments.imagery.empty()) options.imagery = arguments.imagery;
  options.scene.maximumScreenSpaceErrorPixels = *sse;
  options.scene.maximumLoadLevel = arguments.maxLoadLevel;
  if (!applySceneArguments("snapshot", common, context, options.scene)) return 2;
  auto report = runSnapshot(options);
  if (!report) {
    std::fprintf(stderr, "globe snapshot: %s\n", report.error().c_str());
    return 1;
  }
  std::printf("%s: %u tiles drawn, %llu triangles, %llu tile loads, %.2f s\n",
              arguments.output.c_str(), report->tilesDrawn,
              static_cast<unsigned long long>(report->triangles),
              static_cast<unsigned long long>(report->tileLoads), report->seconds);
  if (arguments.verbose) {
    std::printf("terrain under the camera: %s\n",
                report->terrainData.empty() ? "not known (the source names no files)"
                                            : report->terrainData.c_str());
    for (size_t k = 0; k < report->layerExposures.size(); ++k) {
      std::printf("layer %zu exposure: %.2f%s\n", k + 1, report->layerExposures[k],
                  report->layerExposures[k] > 1.0f ? " (a dark photo lifted: --exposure)" : "");
    }
  }
  if (report->failures > 0 && !arguments.allowMissing) {
    std::fprintf(stderr,
                 "globe snapshot: %llu tile(s) the view wanted failed to load (see above): %s "
                 "draws coarser ground or imagery there; --allow-missing accepts such an image\n",
                 static_cast<unsigned long long>(report->failures), arguments.output.c_str());
    return 1;
  }
  return 0;
}

}  // namespace

Subcommand addSnapshotCommand(CLI::App& app, CommonArguments& common) {
  CLI::App* snapshot = app.add_subcommand(
      "snapshot", "render one view headless (OSMesa) once every tile it needs is loaded");
  auto arguments = std::make_shared<SnapshotArguments>();
  addPyramidArgument(*snapshot, arguments->pyramid, common);
  arguments->cameraOption = snapshot->add_option(
      "--camera", arguments->camera,
      "LON,LAT,HEIGHT[,HEADING,PITCH,ROLL]: degrees, metres above the ellipsoid; "
      "heading 0 = north, pitch -90 = straight down (default)");
  snapshot->add_option("--go-to", arguments->goTo,
                       "a place's name (globe search) or a position: the camera ~15 km from it, "
                       "looking at it from the south (instead of --camera)");
  snapshot->add_option("--view", arguments->view,
                       "a view saved by name (V in the window, globe views) instead of --camera");
  snapshot->add_option("--size", arguments->size, "WxH pixels")->capture_default_str();
  snapshot->add_option("-o,--output", arguments->output, "PNG file to write")->required();
  snapshot->add_flag("--above-terrain", arguments->aboveTerrain,
                     "HEIGHT is above the terrain, not the ellipsoid");
  addImageryOption(*snapshot, arguments->imagery);
  snapshot->add_option("--sse", arguments->sse, "maximum screen-space error in pixels (0.1..10000)")
      ->capture_default_str();
  snapshot->add_option("--max-load-level", arguments->maxLoadLevel,
                       "never load tiles deeper than this (shows a view mid-refinement)");
  snapshot->add_flag("--no-attribution", arguments->noAttribution,
                     "leave out the data's attribution (stamped at the bottom right for services "
                     "that give one)");
  snapshot->add_flag("--allow-missing", arguments->allowMissing,
                     "exit 0 even when tiles failed to load (drawn coarser there; each is named "
                     "on stderr): by default such an image is written but the exit status is 1");
  snapshot->add_flag("-v,--verbose", arguments->verbose,
                     "also say what the terrain under the camera was made from (file, spacing)");
  snapshot->add_option("--timeout", arguments->timeoutSeconds,
                       "the longest to wait for the view's tiles, in seconds: past it nothing is "
                       "written and the exit status is 1")
      ->capture_default_str()
      ->check(CLI::Range(1, 86400));
  addGlobeOption(*snapshot, common);
  addNetworkOptions(*snapshot, common);
  addSeaFloorOption(*snapshot, common);
  addLayerOptions(*snapshot, common);
  return {snapshot, [arguments, &common](const CommandContext& context) {
            return runSnapshotCommand(*arguments, common, context);
          }};
}

}  // namespace globe::app
