// globe-bench: QOTCD against the sphere-tree baseline (the paper's Fig. 7) with Google
// Benchmark, or with --accuracy the run time against error table of the four methods.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "tools/bench/accuracy.hpp"
#include "tools/bench/bench_terrain.hpp"
#include "tools/bench/ratio_reporter.hpp"
#include "tools/bench/timing_benchmarks.hpp"

namespace {

void printUsage() {
  std::printf(
      "globe-bench [--pyramid DIR] [Google Benchmark flags]\n"
      "globe-bench --accuracy [--pyramid DIR] [--out DIR] [--queries-per-region N]\n"
      "  --pyramid DIR            a pyramid of the bundled data (default: tile data/dem into a\n"
      "                           temporary directory, ~1 s)\n"
      "  --accuracy               run time against error on 3 x N fixed queries (no benchmarks)\n"
      "  --out DIR                where --accuracy writes accuracy.csv and accuracy.json\n"
      "  --queries-per-region N   default 40000 (three regions)\n"
      "Benchmarks: BM_SphereTree, BM_QotcdLinear, BM_QotcdIndexed, BM_ExactSurface,\n"
      "BM_QotcdIndexedRandom, each /10 /100 /1000 /10000 /100000 tiles; --benchmark_filter,\n"
      "--benchmark_format=json, --benchmark_repetitions etc. as usual.\n");
}

}  // namespace

int main(int argc, char** argv) {
  // Our flags are taken out of argv; the rest goes to Google Benchmark.
  std::filesystem::path pyramidDirectory, outputDirectory;
  bool accuracy = false;
  unsigned long queriesPerRegion = 40000;
  std::vector<char*> rest = {argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&](const char* name) -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "globe-bench: %s needs a value\n", name);
        std::exit(2);
      }
      return argv[++i];
    };
    if (arg == "--pyramid") {
      pyramidDirectory = value("--pyramid");
    } else if (arg == "--accuracy") {
      accuracy = true;
    } else if (arg == "--out") {
      outputDirectory = value("--out");
    } else if (arg == "--queries-per-region") {
      queriesPerRegion = std::strtoul(value("--queries-per-region"), nullptr, 10);
    } else if (arg == "--help" || arg == "-h") {
      printUsage();
      return 0;
    } else {
      rest.push_back(argv[i]);
    }
  }
  if (accuracy) {
    if (rest.size() > 1) {
      std::fprintf(stderr, "globe-bench: unknown argument %s\n", rest[1]);
      return 2;
    }
    auto pyramid = globe::bench::Pyramid::open(pyramidDirectory);
    if (!pyramid) {
      std::fprintf(stderr, "globe-bench: %s\n", pyramid.error().c_str());
      return 1;
    }
    globe::bench::AccuracyOptions options;
    options.outputDirectory = outputDirectory;
    options.queriesPerRegion = static_cast<uint32_t>(queriesPerRegion);
    return globe::bench::runAccuracy(**pyramid, options);
  }
  globe::bench::registerTimingBenchmarks(pyramidDirectory);
  int benchmarkArgc = static_cast<int>(rest.size());
  rest.push_back(nullptr);
  benchmark::Initialize(&benchmarkArgc, rest.data());
  if (benchmark::ReportUnrecognizedArguments(benchmarkArgc, rest.data())) return 1;
  globe::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
