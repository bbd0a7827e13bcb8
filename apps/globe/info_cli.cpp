// `globe info DIR [--json]`: its options, and what it prints.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/globe/info_command.hpp"
#include "apps/globe/subcommands.hpp"

namespace globe::app {
namespace {

struct InfoArguments {
  std::string location;
  bool json = false;
};

int runInfoCommand(const InfoArguments& arguments, const CommandContext& context) {
  InfoOptions options;
  options.location = arguments.location;
  options.json = arguments.json;
  options.network = context.network;
  auto text = runInfo(options);
  if (!text) {
    std::fprintf(stderr, "globe info: %s\n", text.error().c_str());
    return 1;
  }
  std::fputs(text->c_str(), stdout);
  return 0;
}

}  // namespace

Subcommand addInfoCommand(CLI::App& app, CommonArguments& common) {
  CLI::App* info = app.add_subcommand(
      "info", "print a pyramid's (or an imagery layer's) levels, tile counts, bounds and sources");
  auto arguments = std::make_shared<InfoArguments>();
  info->add_option("DIR", arguments->location,
                   "pyramid or imagery layer made by globe-tiler (a directory or its http(s) "
                   "URL), a terrain or imagery service, or a source's name (globe sources)")
      ->required()
      ->transform(CLI::Validator(
          [&common](std::string& text) -> std::string {
            for (auto kind : {services::SourceKind::Terrain, services::SourceKind::Imagery}) {
              auto resolved = resolveSourceName(common, text, kind);
              if (resolved) {
                text = *resolved;
                return {};
              }
            }
            return {};
          },
          "", "named source"));
  info->add_flag("--json", arguments->json, "machine-readable output");
  addGlobeOption(*info, common);
  addNetworkOptions(*info, common);
  return {info, [arguments](const CommandContext& context) {
            return runInfoCommand(*arguments, context);
          }};
}

}  // namespace globe::app
