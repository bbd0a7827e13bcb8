// Commands whose output several test processes read (an export tree, say), run once per CTest
// run as a shared fixture: each process gets the folder and every command's exit and output.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/command_run.hpp"

namespace globe::testing {

struct SharedRun {
  std::filesystem::path dir;       // the fixture folder; "{dir}" in a command stood for it
  std::vector<CommandExit> exits;  // one per command, in order
};

// Runs `commands` in order (each one whatever the last one's exit) into a folder shared under
// `key` (sharedFixture), recording each exit status and output in it beside what they write.
SharedRun sharedCommands(const std::string& key, const std::vector<std::string>& commands);

}  // namespace globe::testing
