// Running a program from a test: its exit status and everything it printed (stdout and stderr).
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace globe::testing {

struct CommandExit {
  int exitCode = -1;  // -1 when it did not exit normally
  std::string output;
};

inline CommandExit runCommand(const std::string& command) {
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  CommandExit r;
  char buffer[4096];
  while (pipe != nullptr && std::fgets(buffer, sizeof buffer, pipe) != nullptr) r.output += buffer;
  const int status = pipe != nullptr ? ::pclose(pipe) : -1;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace globe::testing
