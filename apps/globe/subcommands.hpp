// The `globe` subcommands as main sees them: each add...Command (in <name>_cli.cpp) declares its
// subcommand and options on the program's CLI::App and returns what runs when it was chosen, which
// turns the parsed text into the subcommand's options, runs it (<name>_command.hpp) and prints.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

#include "apps/globe/common_options.hpp"

namespace globe::app {

struct Subcommand {
  CLI::App* command = nullptr;  // command->parsed(): this one was chosen
  // The process's exit code: 0, 1 (the command failed), 2 (bad arguments).
  std::function<int(const CommandContext& context)> run;
};

// In the order `globe --help` lists them. `common` must outlive the returned run.
Subcommand addInfoCommand(CLI::App& app, CommonArguments& common);
Subcommand addSnapshotCommand(CLI::App& app, CommonArguments& common);
Subcommand addQueryCommand(CLI::App& app, CommonArguments& common);
Subcommand addViewCommand(CLI::App& app, CommonArguments& common);
Subcommand addPlayCommand(CLI::App& app, CommonArguments& common);
Subcommand addPathCommand(CLI::App& app, CommonArguments& common);
Subcommand addSourcesCommand(CLI::App& app, CommonArguments& common);
Subcommand addSearchCommand(CLI::App& app, CommonArguments& common);
Subcommand addProfileCommand(CLI::App& app, CommonArguments& common);
Subcommand addSunCommand(CLI::App& app, CommonArguments& common);
Subcommand addViewsCommand(CLI::App& app, CommonArguments& common);
Subcommand addRegressCommand(CLI::App& app, CommonArguments& common);
// Hidden: what `globe regress` starts to render its views (snapshot_worker_cli.cpp).
Subcommand addSnapshotWorkerCommand(CLI::App& app);

}  // namespace globe::app
