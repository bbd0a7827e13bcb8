#include "apps/globe-tiler/export_progress.hpp"

#include <cstdio>
#include <utility>

namespace globe::tiler_app {
namespace {

// The rate is taken once this share of the run, or this long, has passed (whichever first).
constexpr double kEstimateFraction = 0.02;
constexpr double kEstimateSeconds = 5.0;

}  // namespace

ExportProgressPrinter::ExportProgressPrinter(std::string format, unsigned threads, bool quiet,
                                             bool bar)
    : format_(std::move(format)), threads_(threads), quiet_(quiet), bar_(bar && !quiet) {}

void ExportProgressPrinter::report(uint64_t done, uint64_t total) {
  if (quiet_) return;
  done_ = done, total_ = total;
  if (!planned_) {
    planned_ = true;
    start_ = std::chrono::steady_clock::now();
    std::fprintf(stderr, "globe-tiler export: %llu %s tiles to make on %u thread%s\n",
                 static_cast<unsigned long long>(total), format_.c_str(), threads_,
                 threads_ == 1 ? "" : "s");
    return;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (!estimated_ && done > 0 && done < total &&
      (static_cast<double>(done) >= kEstimateFraction * static_cast<double>(total) ||
       seconds >= kEstimateSeconds)) {
    estimated_ = true;
    const double expected = seconds * static_cast<double>(total) / static_cast<double>(done);
    std::fprintf(stderr, "globe-tiler export: expected %s in all (%llu tiles in %.1f s so far)\n",
                 formatDuration(expected).c_str(), static_cast<unsigned long long>(done), seconds);
  }
  bar_.report({done, total, format_, false});
}

void ExportProgressPrinter::finish() {
  if (quiet_ || !planned_) return;
  bar_.report({done_, total_, format_, true});
}

}  // namespace globe::tiler_app
