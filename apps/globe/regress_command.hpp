// `globe regress SUITE --out DIR`: every view of a suite rendered by `globe snapshot` in a
// process of its own (--jobs at once) and compared with its reference; --update writes the
// references of the views that are new or changed. docs/regression.md.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "regression/regression_report.hpp"

namespace globe::app {

struct RegressOptions {
  std::filesystem::path suiteFile;
  std::filesystem::path outFolder;
  std::filesystem::path globeExecutable;  // this program: each view runs `globe snapshot`
  bool update = false;
  int jobs = 1;
  std::string filter;          // ECMAScript regex searched in view names; empty: every view
  double budgetSeconds = 0;    // the whole run's; 0: none
};

struct RegressReport {
  std::vector<regression::ViewOutcome> outcomes;  // in the suite's order
  regression::RunSummary summary;
};

// Errors: a bad suite, a bad filter, an --out that cannot be written (exit 2). onView is called
// as each view ends, in the order they end.
Result<RegressReport> runRegress(const RegressOptions& options,
                                 const std::function<void(const regression::ViewOutcome&)>& onView);

// 0 every view passed (or its reference was written), 1 a view differs, 2 a view is an error.
int regressExitCode(const regression::RunSummary& summary);

}  // namespace globe::app
