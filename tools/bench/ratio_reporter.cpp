// Collects each benchmark's time per query and prints the target ratios at the end.
#include "tools/bench/ratio_reporter.hpp"

#include <cstdio>
#include <set>

namespace globe::bench {
namespace {

struct Ratio {
  const char* numerator;
  const char* denominator;
  const char* meaning;
  double target;  // <= this is the goal (0: no goal)
};
constexpr Ratio kRatios[] = {
    {"BM_QotcdIndexed", "BM_FloorKernel", "QOTCD indexed / floor kernel", 1.2},
    {"BM_ExactSurface", "BM_QotcdIndexed", "exact surface / QOTCD indexed", 1.5},
    {"BM_SphereTreeBvh", "BM_QotcdIndexed", "sphere tree + BVH / QOTCD indexed", 0.0},
    {"BM_SphereTree", "BM_QotcdIndexed", "sphere tree (root scan) / QOTCD indexed", 0.0},
};

}  // namespace

void RatioReporter::ReportRuns(const std::vector<Run>& reports) {
  for (const Run& run : reports) {
    if (run.error_occurred) continue;
    const std::string name = run.run_name.function_name;
    long tiles = 0;
    try {
      tiles = std::stol(run.run_name.args);
    } catch (...) {
      continue;
    }
    const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
    const auto key = std::make_pair(name, tiles);
    if (run.run_type == Run::RT_Aggregate && !median) continue;
    if (!median && fromMedian_[key]) continue;
    times_[key] = run.GetAdjustedCPUTime() * 1e9 / benchmark::GetTimeUnitMultiplier(run.time_unit);
    fromMedian_[key] = median;
  }
  ConsoleReporter::ReportRuns(reports);
}

void RatioReporter::Finalize() {
  ConsoleReporter::Finalize();
  std::set<long> sizes;
  for (const auto& [key, time] : times_) sizes.insert(key.second);
  bool header = false;
  for (const Ratio& ratio : kRatios) {
    for (const long tiles : sizes) {
      const auto top = times_.find({ratio.numerator, tiles});
      const auto bottom = times_.find({ratio.denominator, tiles});
      if (top == times_.end() || bottom == times_.end() || !(bottom->second > 0)) continue;
      if (!header) {
        std::printf("\nRatios in this run (CPU time per query):\n");
        header = true;
      }
      const double value = top->second / bottom->second;
      std::printf("  %-42s %7ld tiles  %7.2fx", ratio.meaning, tiles, value);
      if (ratio.target > 0) {
        std::printf("  (goal <= %.1fx: %s)", ratio.target,
                    value <= ratio.target ? "met" : "not met");
      }
      std::printf("\n");
    }
  }
  std::fflush(stdout);
}

}  // namespace globe::bench
