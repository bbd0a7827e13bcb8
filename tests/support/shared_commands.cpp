#include "tests/support/shared_commands.hpp"

#include <fstream>
#include <iterator>

#include "tests/support/shared_fixture.hpp"

namespace globe::testing {
namespace {

namespace fs = std::filesystem;

std::string withDir(std::string command, const fs::path& dir) {
  const std::string token = "{dir}";
  for (size_t at = command.find(token); at != std::string::npos; at = command.find(token, at)) {
    command.replace(at, token.size(), dir.string());
    at += dir.string().size();
  }
  return command;
}

// The record of command `index`: its exit status on the first line, then its output.
fs::path recordPath(const fs::path& dir, size_t index) {
  return dir / "commands" / (std::to_string(index) + ".txt");
}

CommandExit readRecord(const fs::path& path) {
  std::ifstream in(path);
  CommandExit exit;
  if (!(in >> exit.exitCode)) return {-1, "no record of the command in " + path.string()};
  in.get();  // the newline after the status
  exit.output.assign(std::istreambuf_iterator<char>(in), {});
  return exit;
}

}  // namespace

SharedRun sharedCommands(const std::string& key, const std::vector<std::string>& commands) {
  std::string fullKey = key;
  for (const std::string& command : commands) fullKey += "\n" + command;
  SharedRun run;
  run.dir = sharedFixture(fullKey, [&](const fs::path& dir) {
    fs::create_directories(dir / "commands");
    for (size_t i = 0; i < commands.size(); ++i) {
      const CommandExit exit = runCommand(withDir(commands[i], dir));
      std::ofstream(recordPath(dir, i)) << exit.exitCode << "\n" << exit.output;
    }
    return true;
  });
  for (size_t i = 0; i < commands.size(); ++i)
    run.exits.push_back(readRecord(recordPath(run.dir, i)));
  return run;
}

}  // namespace globe::testing
