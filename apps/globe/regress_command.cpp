#include "apps/globe/regress_command.hpp"

#include <regex.h>
#include <unistd.h>

#include <chrono>

#include "apps/globe/regress_view.hpp"
#include "apps/globe/snapshot_processes.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;
using regression::ViewOutcome;

// Past the snapshot's own --timeout (its wait for tiles), the time to start, draw and write.
constexpr double kProcessGraceSeconds = 60;

// POSIX extended regular expressions (as grep -E), searched anywhere in a view's name.
Result<std::vector<const regression::RegressionView*>> selectedViews(
    const regression::RegressionSuite& suite, const std::string& filter) {
  regex_t pattern;
  if (const int err = ::regcomp(&pattern, filter.empty() ? "." : filter.c_str(),
                                REG_EXTENDED | REG_NOSUB);
      err != 0) {
    char reason[256];
    ::regerror(err, &pattern, reason, sizeof reason);
    return makeError("--filter \"" + filter + "\" is not a regular expression: " + reason);
  }
  std::vector<const regression::RegressionView*> views;
  for (const auto& view : suite.views) {
    if (::regexec(&pattern, view.name.c_str(), 0, nullptr, 0) == 0) views.push_back(&view);
  }
  ::regfree(&pattern);
  if (views.empty()) return makeError("--filter \"" + filter + "\" selects no view of the suite");
  return views;
}

SnapshotJob jobFor(const regression::RegressionSuite& suite, const regression::RegressionView& view,
                   const fs::path& outFolder) {
  SnapshotJob job;
  job.arguments = {"snapshot"};
  job.arguments.insert(job.arguments.end(), view.snapshotArguments.begin(),
                       view.snapshotArguments.end());
  bool timeoutGiven = false;
  for (const std::string& a : view.snapshotArguments) {
    timeoutGiven = timeoutGiven || a == "--timeout" || a.starts_with("--timeout=");
  }
  if (!timeoutGiven) {
    job.arguments.insert(job.arguments.end(), {"--timeout", std::to_string(suite.timeoutSeconds)});
  }
  job.arguments.insert(job.arguments.end(), {"-o", actualPath(outFolder, view.name).string()});
  job.workingFolder = suite.folder;
  job.logFile = outFolder / (view.name + ".log");
  job.timeoutSeconds = suite.timeoutSeconds + kProcessGraceSeconds;
  return job;
}

}  // namespace

Result<RegressReport> runRegress(const RegressOptions& options,
                                 const std::function<void(const ViewOutcome&)>& onView) {
  auto suite = regression::loadRegressionSuite(options.suiteFile);
  if (!suite) return makeError(suite.error());
  suite->folder = fs::absolute(suite->folder);
  auto views = selectedViews(*suite, options.filter);
  if (!views) return makeError(views.error());
  std::error_code error;
  const fs::path out = fs::absolute(options.outFolder);
  fs::create_directories(out, error);
  if (error || !fs::is_directory(out)) {
    return makeError(out.string() + ": cannot make the output folder: " + error.message());
  }
  std::vector<SnapshotJob> jobs;
  for (const auto* view : *views) jobs.push_back(jobFor(*suite, *view, out));
  RegressReport report;
  report.outcomes.resize(jobs.size());
  const auto start = std::chrono::steady_clock::now();
  const int64_t startedUtc = std::chrono::duration_cast<std::chrono::seconds>(
                                 std::chrono::system_clock::now().time_since_epoch())
                                 .count();
  runSnapshotJobs(options.globeExecutable, jobs, std::max(1, options.jobs), options.budgetSeconds,
                  [&](size_t index, const SnapshotExit& exit) {
                    report.outcomes[index] =
                        judgeView(*suite, *(*views)[index], out, exit, options.update);
                    onView(report.outcomes[index]);
                  });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.summary = regression::summarize(report.outcomes, seconds);
  report.summary.startedUtcSeconds = startedUtc;
  if (char host[256] = {}; ::gethostname(host, sizeof host - 1) == 0 && host[0] != '\0') {
    report.summary.hostname = host;
  }
  const std::string name = options.suiteFile.stem().string();
  for (auto written : {regression::writeJsonReport(out, report.outcomes, report.summary),
                       regression::writeJunitReport(out, name, report.outcomes, report.summary),
                       regression::writeHtmlReport(out, name, report.outcomes, report.summary)}) {
    if (!written) return makeError(written.error());
  }
  return report;
}

int regressExitCode(const regression::RunSummary& summary) {
  if (summary.errors > 0) return 2;
  return summary.failed > 0 ? 1 : 0;
}

}  // namespace globe::app
