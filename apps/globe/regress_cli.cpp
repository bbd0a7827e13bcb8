// `globe regress SUITE --out DIR [--update] [--jobs N] [--filter REGEX] [--budget S]`: its
// options, and a line per view as each ends, then the summary and where the reports are.
#include <cstdio>
#include <memory>
#include <string>
#include <thread>

#include "apps/globe/regress_command.hpp"
#include "apps/globe/subcommands.hpp"

namespace globe::app {
namespace {

struct RegressArguments {
  std::string suite;
  std::string out;
  bool update = false;
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::string filter;
  double budgetSeconds = 0;
};

void printView(const regression::ViewOutcome& o) {
  std::string metrics;
  if (o.hasMetrics) {
    char text[96];
    std::snprintf(text, sizeof text, " (%.5f of pixels differ, SSIM %.4f)", o.differingFraction,
                  o.meanSsim);
    metrics = text;
  }
  const bool bad =
      o.status == regression::ViewStatus::fail || o.status == regression::ViewStatus::error;
  std::FILE* stream = bad ? stderr : stdout;
  std::fprintf(stream, "%-7s %s%s %.2f s%s%s\n", regression::statusName(o.status), o.name.c_str(),
               metrics.c_str(), o.seconds, o.message.empty() ? "" : ": ", o.message.c_str());
  std::fflush(stream);
}

int runRegressCommand(const RegressArguments& arguments) {
  RegressOptions options;
  options.suiteFile = arguments.suite;
  options.outFolder = arguments.out;
  options.update = arguments.update;
  options.jobs = arguments.jobs;
  options.filter = arguments.filter;
  options.budgetSeconds = arguments.budgetSeconds;
  std::error_code error;
  options.globeExecutable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) {
    std::fprintf(stderr, "globe regress: cannot find this program to run its views: %s\n",
                 error.message().c_str());
    return 2;
  }
  auto report = runRegress(options, printView);
  if (!report) {
    std::fprintf(stderr, "globe regress: %s\n", report.error().c_str());
    return 2;
  }
  const auto& s = report->summary;
  std::printf("%zu views in %.1f s: %zu passed, %zu failed, %zu errors, %zu references written; "
              "reports in %s (report.html, report.json, junit.xml)\n",
              report->outcomes.size(), s.seconds, s.passed, s.failed, s.errors, s.updated,
              arguments.out.c_str());
  return regressExitCode(s);
}

}  // namespace

Subcommand addRegressCommand(CLI::App& app, CommonArguments& /*common*/) {
  CLI::App* regress = app.add_subcommand(
      "regress", "screenshot regression: render a suite's views and compare them with their "
                 "references (exit 0 all match, 1 one differs, 2 an error)");
  auto arguments = std::make_shared<RegressArguments>();
  regress->add_option("suite", arguments->suite,
                      "the suite: a JSON file of named views (docs/regression.md)")
      ->required();
  regress->add_option("--out", arguments->out,
                      "folder for report.html, report.json, junit.xml and each failed view's "
                      "images")
      ->required();
  regress->add_flag("--update", arguments->update,
                    "write the references of the views that are new or differ (and say which)");
  regress->add_option("--jobs", arguments->jobs, "views rendered at once (default: the cores)")
      ->check(CLI::Range(1, 256));
  regress->add_option("--filter", arguments->filter,
                      "only the views whose names this regular expression finds");
  regress->add_option("--budget", arguments->budgetSeconds,
                      "the longest the whole run may take, in seconds: past it the views still "
                      "running are killed and the rest not started (each an error)")
      ->check(CLI::Range(0.0, 1e6));
  return {regress, [arguments](const CommandContext&) { return runRegressCommand(*arguments); }};
}

}  // namespace globe::app
