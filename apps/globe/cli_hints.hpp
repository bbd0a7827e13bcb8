// Help for a mistyped command line: the subcommand or option the user most likely meant.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace globe::app {

// "did you mean ...?" lines for the words of `arguments` (arguments[0] the program) that name no
// subcommand or option of `app`; "" when there is nothing close to suggest.
std::string mistakeHints(CLI::App& app, const std::vector<std::string>& arguments);

}  // namespace globe::app
