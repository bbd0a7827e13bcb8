#include "apps/globe/stderr_warnings.hpp"

#include <cstdio>
#include <string>

namespace globe::app {

core::WarningSink stderrWarnings() {
  return [](const std::string& warning) { std::fprintf(stderr, "globe: %s\n", warning.c_str()); };
}

}  // namespace globe::app
