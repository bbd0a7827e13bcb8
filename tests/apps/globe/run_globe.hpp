// Runs the real `globe` (GLOBE_EXE, set by the test target) with arguments, stdout and stderr
// together: the app tests' way to drive the program as a user does.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

#include "tests/support/build_paths.hpp"

namespace globe::app::test {

struct ProcessResult {
  int exitCode;
  std::string output;
};

inline ProcessResult runGlobe(const std::string& arguments) {
  const std::string command = std::string(GLOBE_EXE) + " " + arguments + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer{};
  while (pipe != nullptr && std::fgets(buffer.data(), buffer.size(), pipe) != nullptr)
    output += buffer.data();
  const int status = pipe != nullptr ? ::pclose(pipe) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

}  // namespace globe::app::test
