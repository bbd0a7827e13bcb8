// The Google Benchmark cases of globe-bench (the paper's Fig. 7): BM_SphereTree, BM_QotcdLinear,
// BM_QotcdIndexed and BM_ExactSurface along a flight path, BM_QotcdIndexedRandom at random.
#pragma once

#include <filesystem>

namespace globe::bench {

// Registers the cases for 10 .. 100,000 tiles. The pyramid (the directory, or the bundled data
// tiled on first use when it is empty) and the arrays are built when a case first needs them.
void registerTimingBenchmarks(const std::filesystem::path& pyramidDirectory);

}  // namespace globe::bench
