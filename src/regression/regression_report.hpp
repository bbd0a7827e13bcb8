// What globe regress found for each view, and the three reports it writes into --out:
// report.json (for programs), junit.xml (for CI systems) and report.html (for people: each failing
// view's expected, actual and diff images side by side). docs/regression.md describes them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "regression/regression_suite.hpp"

namespace globe::regression {

enum class ViewStatus { pass, fail, error, updated };

const char* statusName(ViewStatus status);  // "pass", "fail", "error", "updated"

struct ViewOutcome {
  std::string name;
  ViewStatus status = ViewStatus::error;
  Tolerance tolerance;
  // The metrics (compared views only; hasMetrics false otherwise).
  bool hasMetrics = false;
  double differingFraction = 1;
  int largestChannelDifference = 255;
  double meanSsim = 0;
  double lowestWindowSsim = 0;
  double seconds = 0;   // rendering and comparing
  std::string message;  // why it failed, or the error; empty for a pass
  bool imagesWritten = false;  // NAME.expected.png, NAME.actual.png, NAME.diff.png in --out
};

struct RunSummary {
  size_t passed = 0, failed = 0, errors = 0, updated = 0;
  double seconds = 0;
  // When and where it ran (junit.xml's timestamp and hostname): UTC, seconds since 1970.
  int64_t startedUtcSeconds = 0;
  std::string hostname = "localhost";
};

RunSummary summarize(const std::vector<ViewOutcome>& outcomes, double seconds);

// Each written atomically into `outFolder`; errors name the file.
Result<void> writeJsonReport(const std::filesystem::path& outFolder,
                             const std::vector<ViewOutcome>& outcomes, const RunSummary& summary);
Result<void> writeJunitReport(const std::filesystem::path& outFolder, const std::string& suiteName,
                              const std::vector<ViewOutcome>& outcomes,
                              const RunSummary& summary);
Result<void> writeHtmlReport(const std::filesystem::path& outFolder, const std::string& suiteName,
                             const std::vector<ViewOutcome>& outcomes, const RunSummary& summary);

}  // namespace globe::regression
