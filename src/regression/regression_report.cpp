#include "regression/regression_report.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "transport/atomic_file.hpp"

namespace globe::regression {

const char* statusName(ViewStatus status) {
  static constexpr const char* kNames[] = {"pass", "fail", "error", "updated"};
  return kNames[static_cast<int>(status)];
}

RunSummary summarize(const std::vector<ViewOutcome>& outcomes, double seconds) {
  RunSummary summary;
  summary.seconds = seconds;
  for (const ViewOutcome& o : outcomes) {
    size_t* counts[] = {&summary.passed, &summary.failed, &summary.errors, &summary.updated};
    ++*counts[static_cast<int>(o.status)];
  }
  return summary;
}

Result<void> writeJsonReport(const std::filesystem::path& outFolder,
                             const std::vector<ViewOutcome>& outcomes, const RunSummary& summary) {
  nlohmann::json views = nlohmann::json::array();
  for (const ViewOutcome& o : outcomes) {
    nlohmann::json view = {
        {"name", o.name},
        {"status", statusName(o.status)},
        {"tolerance",
         {{"channel", o.tolerance.channelThreshold},
          {"fraction", o.tolerance.differingFraction},
          {"ssim", o.tolerance.minimumSsim}}},
        {"seconds", std::round(o.seconds * 1000) / 1000},
        {"message", o.message}};
    // null where the view was not compared (an error, a new view): never a made-up figure.
    view["differingFraction"] = o.hasMetrics ? nlohmann::json(o.differingFraction) : nullptr;
    view["largestChannelDifference"] =
        o.hasMetrics ? nlohmann::json(o.largestChannelDifference) : nullptr;
    view["ssim"] = o.hasMetrics ? nlohmann::json(o.meanSsim) : nullptr;
    view["lowestWindowSsim"] = o.hasMetrics ? nlohmann::json(o.lowestWindowSsim) : nullptr;
    if (o.imagesWritten) {
      view["images"] = {{"expected", o.name + ".expected.png"},
                        {"actual", o.name + ".actual.png"},
                        {"diff", o.name + ".diff.png"}};
    }
    views.push_back(std::move(view));
  }
  const nlohmann::json report = {{"passed", summary.passed}, {"failed", summary.failed},
                                 {"errors", summary.errors}, {"updated", summary.updated},
                                 {"seconds", std::round(summary.seconds * 1000) / 1000},
                                 {"views", views}};
  return transport::writeFileAtomically(outFolder / "report.json", report.dump(2) + "\n");
}

}  // namespace globe::regression
