// `globe query PYRAMID`: its options, their conversion into QueryOptions, and its exit code.
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "apps/globe/query_command.hpp"
#include "apps/globe/subcommands.hpp"

namespace globe::app {
namespace {

struct QueryArguments {
  std::string pyramid;
  std::string mode = "qotcd";
  uint32_t level = 0;
  CLI::Option* levelOption = nullptr;  // count() > 0: --level was given
  std::vector<std::string> tilesets;
};

int runQueryCommand(const QueryArguments& arguments, const CommandContext& context) {
  QueryOptions options;
  options.pyramid = arguments.pyramid;
  options.globeModel = context.globeModel;
  options.sea = context.sea;
  options.network = context.network;
  options.tilesets.assign(arguments.tilesets.begin(), arguments.tilesets.end());
  if (arguments.mode == "exact") {
    options.mode = collision::HeightMode::Exact;
  } else if (arguments.mode != "qotcd") {
    std::fprintf(stderr, "globe query: --mode must be qotcd or exact, not '%s'\n",
                 arguments.mode.c_str());
    return 2;
  }
  if (arguments.levelOption->count() > 0) options.level = arguments.level;
  auto report = runQuery(options, std::cin, stdout, stderr);
  if (!report) {
    std::fprintf(stderr, "globe query: %s\n", report.error().c_str());
    return 1;
  }
  return report->rejected > 0 ? 1 : 0;
}

}  // namespace

Subcommand addQueryCommand(CLI::App& app, CommonArguments& common) {
  CLI::App* query = app.add_subcommand(
      "query", "heights: reads lon,lat lines (degrees) on stdin, prints lon,lat,level,height_m");
  auto arguments = std::make_shared<QueryArguments>();
  addPyramidArgument(*query, arguments->pyramid, common);
  query
      ->add_option("--mode", arguments->mode,
                   "qotcd (the paper's conservative height) | exact (the drawn surface)")
      ->capture_default_str();
  arguments->levelOption = query->add_option("--level", arguments->level,
                                             "query this level (default: the finest there)");
  query->add_option("--tileset", arguments->tilesets,
                    "3D Tiles tileset (its tileset.json or folder): the height is the higher of "
                    "the terrain and its finest content there; repeat for more");
  addGlobeOption(*query, common);
  addNetworkOptions(*query, common);
  addSeaFloorOption(*query, common);
  return {query, [arguments](const CommandContext& context) {
            return runQueryCommand(*arguments, context);
          }};
}

}  // namespace globe::app
