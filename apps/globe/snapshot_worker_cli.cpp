// `globe snapshot-worker` (hidden): renders one view after another in one process, as globe
// regress sends them, so that a suite pays the program's start (its libraries' loading, ~0.2 s)
// once per worker rather than once per view. Each request is one line of JSON on stdin,
//   {"folder": DIR, "log": FILE, "arguments": ["snapshot", ARGS..., "-o", PNG]}
// run exactly as `globe snapshot ARGS...` in DIR would run, with fresh options and state, its
// output to FILE; the answer is one line on stdout, {"exit": CODE}. EOF on stdin ends the worker.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "apps/globe/globe_command_line.hpp"
#include "apps/globe/subcommands.hpp"

namespace globe::app {
namespace {

struct Request {
  std::string folder, log;
  std::vector<std::string> arguments;
};

// A request, or an error saying what is wrong with the line.
bool parseRequest(const std::string& line, Request& request, std::string& error) {
  try {
    const auto j = nlohmann::json::parse(line);
    request.folder = j.at("folder").get<std::string>();
    request.log = j.at("log").get<std::string>();
    request.arguments = j.at("arguments").get<std::vector<std::string>>();
  } catch (const nlohmann::json::exception& e) {
    error = std::string("a request is not {folder, log, arguments}: ") + e.what();
    return false;
  }
  if (request.arguments.empty() || request.arguments[0] != "snapshot") {
    error = "a worker runs `snapshot` only";
    return false;
  }
  return true;
}

// Runs one view with stdout and stderr in its log; the exit code (2 when it could not start).
int runView(const Request& request) {
  const int log = ::open(request.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log < 0 || ::chdir(request.folder.c_str()) != 0) {  // said on the worker's own stderr
    std::fprintf(stderr, "globe snapshot-worker: %s: %s\n",
                 (log < 0 ? request.log : request.folder).c_str(), std::strerror(errno));
    if (log >= 0) ::close(log);
    return 2;
  }
  std::fflush(stdout);
  std::fflush(stderr);
  const int savedOut = ::dup(STDOUT_FILENO), savedErr = ::dup(STDERR_FILENO);
  ::dup2(log, STDOUT_FILENO);
  ::dup2(log, STDERR_FILENO);
  ::close(log);
  std::vector<std::string> argv = {"globe"};
  argv.insert(argv.end(), request.arguments.begin(), request.arguments.end());
  int code = 1;
  try {
    code = runGlobeCommandLine(argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "globe snapshot: %s\n", e.what());
  }
  std::fflush(stdout);
  std::fflush(stderr);
  ::dup2(savedOut, STDOUT_FILENO);
  ::dup2(savedErr, STDERR_FILENO);
  ::close(savedOut);
  ::close(savedErr);
  return code;
}

int serveViews() {
  for (std::string line; std::getline(std::cin, line);) {
    Request request;
    std::string error;
    int code = 2;
    if (parseRequest(line, request, error)) {
      code = runView(request);
    } else {
      std::fprintf(stderr, "globe snapshot-worker: %s\n", error.c_str());
    }
    std::printf("{\"exit\": %d}\n", code);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace

Subcommand addSnapshotWorkerCommand(CLI::App& app) {
  CLI::App* worker = app.add_subcommand(
      "snapshot-worker", "render the views sent on stdin, one JSON request a line (globe regress)");
  worker->group("");  // not in --help: globe regress's, not a user's
  return {worker, [](const CommandContext&) { return serveViews(); }};
}

}  // namespace globe::app
