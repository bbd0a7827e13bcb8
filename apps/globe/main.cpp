// globe: the virtual-globe viewer's command line. Each subcommand declares its own options and
// runs in its own file (<name>_cli.cpp, over <name>_command.cpp); the options several share are
// declared once (common_options.cpp).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "apps/globe/common_options.hpp"
#include "apps/globe/subcommands.hpp"
#include "globe_version.hpp"

int main(int argc, char** argv) {
  CLI::App app{"globe: a virtual-globe terrain viewer with real-time camera-terrain collision",
               "globe"};
  app.set_version_flag(
      "--version", std::string("globe ") + globe::kVersion + " (" + globe::sourceRevision() + ")");
  app.require_subcommand(1);
  globe::app::CommonArguments common;
  auto sources = globe::services::loadNamedSources(globe::services::userSourcesFile());
  if (!sources) {
    std::fprintf(stderr, "globe: %s\n", sources.error().c_str());
    return 2;
  }
  common.sources = std::make_shared<const globe::services::NamedSources>(std::move(*sources));
  const std::vector<globe::app::Subcommand> subcommands = {
      globe::app::addInfoCommand(app, common),   globe::app::addSnapshotCommand(app, common),
      globe::app::addQueryCommand(app, common),  globe::app::addViewCommand(app, common),
      globe::app::addPlayCommand(app, common),   globe::app::addSourcesCommand(app, common),
      globe::app::addSearchCommand(app, common), globe::app::addProfileCommand(app, common),
      globe::app::addViewsCommand(app, common),  globe::app::addRegressCommand(app, common)};

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version end here too (exit 0). A mistake in the arguments is exit 2 for every
    // subcommand, as they document, whatever CLI11's own code for the kind of mistake.
    return app.exit(error) == 0 ? 0 : 2;
  }
  const auto context = globe::app::makeCommandContext(common);
  if (!context) return 2;
  for (const globe::app::Subcommand& subcommand : subcommands) {
    if (subcommand.command->parsed()) return subcommand.run(*context);
  }
  return 0;
}
