#include "apps/globe/snapshot_processes.hpp"

#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <list>
#include <nlohmann/json.hpp>
#include <optional>

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

// One `globe snapshot-worker`: a socket to it (its stdin and stdout), the view it is drawing.
struct Worker {
  pid_t pid = -1;
  int socket = -1;
  std::string answer;  // bytes of the answer read so far
  std::optional<Running> job;
};

// posix_spawn (no shell), the socket as its stdin and stdout, its stderr ours (what it says
// outside any view: a bad sources file, a request it could not run).
bool spawnWorker(const std::filesystem::path& exe, Worker& worker, std::string& error) {
  int ends[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) {
    error = std::string("no socket for a worker: ") + std::strerror(errno);
    return false;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, ends[1], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, ends[1], STDOUT_FILENO);
  char name[] = "globe", command[] = "snapshot-worker";
  char* argv[] = {name, command, nullptr};
  const int err = ::posix_spawn(&worker.pid, exe.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(ends[1]);
  if (err != 0) {
    ::close(ends[0]);
    error = exe.string() + " could not be started: " + std::strerror(err);
    return false;
  }
  worker.socket = ends[0];
  return true;
}

bool sendRequest(const Worker& worker, const SnapshotJob& job) {
  const nlohmann::json request = {{"folder", job.workingFolder.string()},
                                  {"log", job.logFile.string()},
                                  {"arguments", job.arguments}};
  const std::string line = request.dump() + "\n";
  for (size_t sent = 0; sent < line.size();) {
    const ssize_t n = ::send(worker.socket, line.data() + sent, line.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    sent += static_cast<size_t>(n);
  }
  return true;
}

// Closes the socket and waits for the process (killed first when `kill`); its wait status.
int retire(Worker& worker, bool kill) {
  if (kill) ::kill(worker.pid, SIGKILL);
  ::close(worker.socket);
  int status = 0;
  while (::waitpid(worker.pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

SnapshotExit exitOfProcess(int status, const Running& run) {
  SnapshotExit exit;
  exit.started = true;
  exit.seconds = secondsSince(run.started);
  exit.timedOut = run.killed;
  if (WIFEXITED(status)) exit.exitCode = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) exit.signal = WTERMSIG(status);
  if (exit.exitCode == 0 && exit.signal == 0) exit.exitCode = 1;  // gone without answering
  return exit;
}

// Reads what the worker sent: the view's exit once its answer line is complete. A worker that
// closed the socket (it died, or was killed) is retired and the view gets its process's end.
std::optional<SnapshotExit> readAnswer(Worker& worker, bool& gone) {
  char bytes[256];
  const ssize_t n = ::recv(worker.socket, bytes, sizeof bytes, 0);
  if (n < 0 && errno == EINTR) return std::nullopt;
  if (n <= 0 || worker.answer.size() > 4096) {
    gone = true;
    return exitOfProcess(retire(worker, true), *worker.job);
  }
  worker.answer.append(bytes, static_cast<size_t>(n));
  const size_t end = worker.answer.find('\n');
  if (end == std::string::npos) return std::nullopt;
  SnapshotExit exit;
  exit.started = true;
  exit.seconds = secondsSince(worker.job->started);
  // {"exit": N} from the worker; anything else (never expected) counts as a failed view.
  const auto answer = nlohmann::json::parse(worker.answer.substr(0, end), nullptr, false);
  const bool understood = answer.is_object() && answer.contains("exit") &&
                          answer["exit"].is_number_unsigned();
  exit.exitCode = understood ? answer["exit"].get<int>() : 1;
  worker.answer.erase(0, end + 1);
  return exit;
}

using OnDone = std::function<void(size_t index, const SnapshotExit& exit)>;

// Waits up to 20 ms for answers; reports each view that ended; kills the workers whose view is
// past its time or the run's budget (their end is reported once their socket closes).
void waitForAnswers(std::list<Worker>& workers, const std::vector<SnapshotJob>& jobs,
                    const std::function<bool()>& budgetSpent, size_t& busy, const OnDone& onDone) {
  std::vector<pollfd> polled;
  std::vector<std::list<Worker>::iterator> owners;
  for (auto it = workers.begin(); it != workers.end(); ++it) {
    if (!it->job) continue;
    polled.push_back({it->socket, POLLIN, 0});
    owners.push_back(it);
  }
  if (polled.empty()) return;
  ::poll(polled.data(), polled.size(), 20);
  for (size_t i = 0; i < polled.size(); ++i) {
    const auto worker = owners[i];
    bool gone = false;
    if (polled[i].revents != 0) {
      if (const auto exit = readAnswer(*worker, gone)) {
        const size_t index = worker->job->index;
        worker->job.reset();
        --busy;
        if (gone) workers.erase(worker);
        onDone(index, *exit);
        continue;
      }
    }
    Running& run = *worker->job;
    if (!run.killed &&
        (secondsSince(run.started) > jobs[run.index].timeoutSeconds || budgetSpent())) {
      ::kill(worker->pid, SIGKILL);
      run.killed = true;
    }
  }
}

}  // namespace

void runSnapshotJobs(const std::filesystem::path& globeExecutable,
                     const std::vector<SnapshotJob>& jobs, int parallel, double budgetSeconds,
                     const std::function<void(size_t index, const SnapshotExit& exit)>& onDone) {
  const Clock::time_point start = Clock::now();
  const auto budgetSpent = [&] { return budgetSeconds > 0 && secondsSince(start) > budgetSeconds; };
  std::list<Worker> workers;
  size_t next = 0, busy = 0;
  while (next < jobs.size() || busy > 0) {
    while (next < jobs.size() && busy < static_cast<size_t>(parallel)) {
      SnapshotExit exit;
      if (budgetSpent()) {
        exit.message = "not started: the run's budget of " + std::to_string(budgetSeconds) +
                       " s was spent";
        onDone(next++, exit);
        continue;
      }
      auto idle = std::find_if(workers.begin(), workers.end(), [](auto& w) { return !w.job; });
      const bool fresh = idle == workers.end();
      if (fresh) {
        Worker started;
        if (!spawnWorker(globeExecutable, started, exit.message)) {
          onDone(next++, exit);
          continue;
        }
        idle = workers.insert(workers.end(), started);
      }
      if (!sendRequest(*idle, jobs[next])) {  // it ended while idle: the view goes to a fresh one
        const int status = retire(*idle, true);
        workers.erase(idle);
        if (fresh) {  // one that ended at once: the view's error, not another try
          exit = exitOfProcess(status, Running{next, Clock::now(), false});
          onDone(next++, exit);
        }
        continue;
      }
      idle->job = Running{next++, Clock::now(), false};
      ++busy;
    }
    waitForAnswers(workers, jobs, budgetSpent, busy, onDone);
  }
  for (Worker& worker : workers) retire(worker, false);  // EOF on its stdin: it ends
}

}  // namespace globe::app
