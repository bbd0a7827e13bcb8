// `globe snapshot` runs in child processes, a few at a time: globe regress sends each view to a
// `globe snapshot-worker` (snapshot_worker_cli.cpp), which draws one view after another in one
// process, so views run in parallel, the program starts once per worker rather than per view, and
// one view's crash or hang is that view's error (its worker is replaced).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace globe::app {

struct SnapshotJob {
  std::vector<std::string> arguments;   // after `globe`: snapshot ARGS... -o FILE
  std::filesystem::path workingFolder;  // where relative paths in the arguments resolve
  std::filesystem::path logFile;        // its stdout and stderr
  double timeoutSeconds = 0;            // killed past it
};

struct SnapshotExit {
  bool started = false;    // false: not started, or its exit lost (message says why)
  int exitCode = -1;       // the process's, when it exited
  int signal = 0;          // the signal that ended it, when one did
  bool timedOut = false;   // killed: past its timeout or the run's budget
  double seconds = 0;
  std::string message;
};

// Runs every job, at most `parallel` at once, in the order given; once `budgetSeconds` (0: none)
// has passed since the start, running jobs are killed and the rest are not started. onDone is
// called in this thread as each job ends (or is given up), with its index.
void runSnapshotJobs(const std::filesystem::path& globeExecutable,
                     const std::vector<SnapshotJob>& jobs, int parallel, double budgetSeconds,
                     const std::function<void(size_t index, const SnapshotExit& exit)>& onDone);

}  // namespace globe::app
