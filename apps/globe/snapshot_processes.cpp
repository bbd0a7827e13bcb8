#include "apps/globe/snapshot_processes.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <map>
#include <thread>

extern char** environ;

namespace globe::app {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Running {
  size_t index = 0;
  Clock::time_point started;
  bool killed = false;
};

// posix_spawn (no shell: arguments go through as they are), in the job's folder, output to its log.
pid_t spawnJob(const std::filesystem::path& exe, const SnapshotJob& job, std::string& error) {
  std::vector<std::string> argv = {"globe"};
  argv.insert(argv.end(), job.arguments.begin(), job.arguments.end());
  std::vector<char*> pointers;
  for (std::string& a : argv) pointers.push_back(a.data());
  pointers.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, job.workingFolder.c_str());
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, job.logFile.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  pid_t pid = -1;
  const int err = ::posix_spawn(&pid, exe.c_str(), &actions, nullptr, pointers.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) {
    error = exe.string() + " could not be started: " + std::strerror(err);
    return -1;
  }
  return pid;
}

SnapshotExit exitOf(int status, const Running& run) {
  SnapshotExit exit;
  exit.started = true;
  exit.seconds = secondsSince(run.started);
  exit.timedOut = run.killed;
  if (WIFEXITED(status)) exit.exitCode = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) exit.signal = WTERMSIG(status);
  return exit;
}

}  // namespace

void runSnapshotJobs(const std::filesystem::path& globeExecutable,
                     const std::vector<SnapshotJob>& jobs, int parallel, double budgetSeconds,
                     const std::function<void(size_t index, const SnapshotExit& exit)>& onDone) {
  const Clock::time_point start = Clock::now();
  const auto budgetSpent = [&] { return budgetSeconds > 0 && secondsSince(start) > budgetSeconds; };
  std::map<pid_t, Running> running;
  size_t next = 0;
  while (next < jobs.size() || !running.empty()) {
    while (next < jobs.size() && static_cast<int>(running.size()) < parallel) {
      SnapshotExit exit;
      if (budgetSpent()) {
        exit.message = "not started: the run's budget of " + std::to_string(budgetSeconds) +
                       " s was spent";
        onDone(next++, exit);
        continue;
      }
      const pid_t pid = spawnJob(globeExecutable, jobs[next], exit.message);
      if (pid < 0) {
        onDone(next++, exit);
        continue;
      }
      running[pid] = Running{next++, Clock::now(), false};
    }
    int status = 0;
    const pid_t done = ::waitpid(-1, &status, WNOHANG);
    if (done > 0 && running.contains(done)) {
      const Running run = running[done];
      running.erase(done);
      onDone(run.index, exitOf(status, run));
      continue;
    }
    if (done < 0 && errno == ECHILD) break;
    // Nothing ended: kill what is past its time, then look again shortly.
    for (auto& [pid, run] : running) {
      if (!run.killed && (secondsSince(run.started) > jobs[run.index].timeoutSeconds ||
                          budgetSpent())) {
        ::kill(pid, SIGKILL);
        run.killed = true;
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

}  // namespace globe::app
