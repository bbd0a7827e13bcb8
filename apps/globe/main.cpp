// globe: the virtual-globe viewer's command line. Each subcommand declares its own options and
// runs in its own file (<name>_cli.cpp, over <name>_command.cpp); the options several share are
// declared once (common_options.cpp).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "apps/globe/cli_hints.hpp"
#include "apps/globe/common_options.hpp"
#include "apps/globe/globe_command_line.hpp"
#include "apps/globe/subcommands.hpp"
#include "globe_version.hpp"

namespace globe::app {

int runGlobeCommandLine(const std::vector<std::string>& arguments) {
  CLI::App app{"globe: a virtual-globe terrain viewer with real-time camera-terrain collision",
               "globe"};
  app.set_version_flag("--version",
                       std::string("globe ") + kVersion + " (" + sourceRevision() + ")");
  app.require_subcommand(1);
  CommonArguments common;
  auto sources = services::loadNamedSources(services::userSourcesFile());
  if (!sources) {
    std::fprintf(stderr, "globe: %s\n", sources.error().c_str());
    return 2;
  }
  common.sources = std::make_shared<const services::NamedSources>(std::move(*sources));
  const std::vector<Subcommand> subcommands = {
      addInfoCommand(app, common),    addSnapshotCommand(app, common),
      addQueryCommand(app, common),   addViewCommand(app, common),
      addPlayCommand(app, common),    addPathCommand(app, common),
      addSourcesCommand(app, common),
      addSearchCommand(app, common),  addProfileCommand(app, common),
      addSunCommand(app, common),     addViewsCommand(app, common),
      addRegressCommand(app, common), addSnapshotWorkerCommand(app)};

  std::vector<const char*> argv;
  for (const std::string& a : arguments) argv.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError& error) {
    // --help and --version end here too (exit 0). A mistake in the arguments is exit 2 for every
    // subcommand, as they document, whatever CLI11's own code for the kind of mistake.
    const int code = app.exit(error);
    if (code != 0) std::fputs(mistakeHints(app, arguments).c_str(), stderr);
    return code == 0 ? 0 : 2;
  }
  const auto context = makeCommandContext(common);
  if (!context) return 2;
  for (const Subcommand& subcommand : subcommands) {
    if (subcommand.command->parsed()) return subcommand.run(*context);
  }
  return 0;
}

}  // namespace globe::app

int main(int argc, char** argv) {
  return globe::app::runGlobeCommandLine(std::vector<std::string>(argv, argv + argc));
}
