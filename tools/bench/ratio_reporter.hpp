// The console report of globe-bench, followed by the ratios the collision targets are stated
// in (QOTCD indexed / the floor kernel, the exact surface / QOTCD indexed, the BVH sphere tree /
// QOTCD indexed), per tile count, from the runs just made: the ratios are what compares across
// machines, not the times.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

namespace globe::bench {

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& reports) override;
  void Finalize() override;

 private:
  // (family, tile count) -> CPU ns per query: the median aggregate if there is one, else the
  // last plain run.
  std::map<std::pair<std::string, long>, double> times_;
  std::map<std::pair<std::string, long>, bool> fromMedian_;
};

}  // namespace globe::bench
