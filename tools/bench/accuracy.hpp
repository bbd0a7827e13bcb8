// globe-bench --accuracy: run time against error of the four methods on a fixed set of queries
// over real terrain, against the drawn surface and the finest source data; a table, CSV and JSON.
#pragma once

#include <cstdint>
#include <filesystem>

#include "tools/bench/bench_terrain.hpp"

namespace globe::bench {

struct AccuracyOptions {
  std::filesystem::path outputDirectory;  // accuracy.csv and accuracy.json; empty: not written
  uint32_t queriesPerRegion = 40000;      // three regions
  uint64_t seed = 20240607;
};

// Returns the process exit status.
int runAccuracy(Pyramid& pyramid, const AccuracyOptions& options);

}  // namespace globe::bench
