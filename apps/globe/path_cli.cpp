// `globe path check PYRAMID PATH [--clearance M] [--rate N]`: where a camera path would go under
// the terrain or nearer to it than the eye clearance, before anything is rendered
// (apps/globe/path_check.hpp). Exit 0: none; 1: stretches found (each printed) or a failure; 2:
// bad arguments.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/globe/camera_argument.hpp"
#include "apps/globe/path_check.hpp"
#include "apps/globe/subcommands.hpp"

namespace globe::app {
namespace {

struct PathArguments {
  std::string pyramid;
  std::string path;
  std::string clearance = "2";
  std::string rate = "30";
  CLI::App* check = nullptr;
};

int runPathCheckCommand(const PathArguments& arguments, const CommonArguments& common,
                        const CommandContext& context) {
  auto clearance = parseNumberArgument("--clearance", arguments.clearance, 0, 1e6);
  auto rate = parseNumberArgument("--rate", arguments.rate, 0, 1000, true);
  if (!clearance || !rate) {
    std::fprintf(stderr, "globe path check: %s\n",
                 (!clearance ? clearance.error() : rate.error()).c_str());
    return 2;
  }
  auto pyramid = resolveSourceName(common, arguments.pyramid, services::SourceKind::Terrain);
  if (!pyramid) {
    std::fprintf(stderr, "globe path check: %s\n", pyramid.error().c_str());
    return 2;
  }
  PathCheckOptions options;
  options.pyramid = *pyramid;
  options.pathFile = arguments.path;
  options.samplesPerSecond = *rate;
  options.clearanceMeters = *clearance;
  options.globeModel = context.globeModel;
  options.sea = context.sea;
  options.network = context.network;
  auto check = runPathCheck(options);
  if (!check) {
    std::fprintf(stderr, "globe path check: %s\n", check.error().c_str());
    return 1;
  }
  std::printf("%s: %.2f s, %zu samples (%g a second), lowest clearance %.1f m\n",
              arguments.path.c_str(), check->durationSeconds, check->samples, *rate,
              check->lowestClearanceMeters);
  for (const PathStretch& stretch : check->stretches) {
    std::printf("%s\n", describeStretch(stretch, *clearance).c_str());
  }
  if (check->stretches.empty()) {
    std::printf("clear: the path keeps %g m above the terrain everywhere\n", *clearance);
    return 0;
  }
  std::printf("%zu stretch(es): globe play's collision response takes over there (the camera "
              "is lifted)\n",
              check->stretches.size());
  return 1;
}

}  // namespace

Subcommand addPathCommand(CLI::App& app, CommonArguments& common) {
  auto arguments = std::make_shared<PathArguments>();
  CLI::App* path = app.add_subcommand("path", "camera path tools: check");
  path->require_subcommand(1);
  CLI::App* check = path->add_subcommand(
      "check",
      "where a camera path (.json or a .kml tour) would go under the terrain or nearer to it "
      "than --clearance, over the pyramid's finest tiles, without rendering: prints each "
      "stretch; exit 1 when there is one");
  addPyramidArgument(*check, arguments->pyramid, common);
  check->add_option("PATH", arguments->path, "camera path: .json keyframes or a .kml gx:Tour")
      ->required();
  check->add_option("--clearance", arguments->clearance,
                    "metres the camera keeps above the terrain (the eye clearance, default 2)");
  check->add_option("--rate", arguments->rate, "samples a second of path time (default 30)");
  addGlobeOption(*check, common);
  addNetworkOptions(*check, common);
  addSeaFloorOption(*check, common);
  arguments->check = check;
  return {path, [arguments, &common](const CommandContext& context) {
            return runPathCheckCommand(*arguments, common, context);
          }};
}

}  // namespace globe::app
