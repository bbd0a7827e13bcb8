// The whole `globe` command line as a function: main runs it once; `globe snapshot-worker` runs
// it once per view it is sent, each time with fresh options, context and subcommand state.
#pragma once

#include <string>
#include <vector>

namespace globe::app {

// arguments[0] is the program's name. The exit code a process running them would give.
int runGlobeCommandLine(const std::vector<std::string>& arguments);

}  // namespace globe::app
