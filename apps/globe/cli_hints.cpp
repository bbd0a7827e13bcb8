#include "apps/globe/cli_hints.hpp"

#include <algorithm>

#include "apps/globe/did_you_mean.hpp"

namespace globe::app {
namespace {

std::vector<std::string> subcommandNames(CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    if (!sub->get_group().empty()) names.push_back(sub->get_name());  // hidden ones stay hidden
  }
  return names;
}

// "--name" for every long option of `command` and of the program (--help, --version).
std::vector<std::string> longOptions(CLI::App& app, CLI::App* command) {
  std::vector<std::string> names;
  for (CLI::App* owner : {&app, command}) {
    if (owner == nullptr) continue;
    for (const CLI::Option* option : owner->get_options()) {
      for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    }
  }
  return names;
}

}  // namespace

std::string mistakeHints(CLI::App& app, const std::vector<std::string>& arguments) {
  if (arguments.size() < 2) return "";
  std::string hints;
  CLI::App* command = nullptr;
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    if (sub->get_name() == arguments[1]) command = sub;
  }
  const std::string& first = arguments[1];
  if (command == nullptr && !first.starts_with("-")) {
    if (auto meant = closestWord(first, subcommandNames(app))) {
      hints += "globe: no subcommand \"" + first + "\"; did you mean `globe " + *meant + "`?\n";
    }
    return hints;
  }
  const std::vector<std::string> known = longOptions(app, command);
  for (size_t i = 2; i < arguments.size(); ++i) {
    const std::string word = arguments[i].substr(0, arguments[i].find('='));
    if (!word.starts_with("--") || std::find(known.begin(), known.end(), word) != known.end()) {
      continue;
    }
    if (auto meant = closestWord(word, known)) {
      hints += "globe: no option " + word + "; did you mean " + *meant + "?\n";
    }
  }
  return hints;
}

}  // namespace globe::app
