// The markdown report of the fill benchmark (docs/performance/fill-accuracy.md): setup, summary, details and
// checks, all from the numbers of one run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "tools/bench_fill/fill_benchmark.hpp"

namespace globe::bench_fill {

struct TileReport {
  std::string name;         // "N50E008"
  std::string description;  // one phrase: what the tile is
  int64_t cols = 0, rows = 0;
  double stepArcSeconds = 0;
  double rowStepKilometres = 0;  // north-south size of one sample
  size_t landSamples = 0, noDataSamples = 0;
  std::vector<ClassResult> classes;
};

struct ReportInput {
  std::string commandLine;
  std::string gdalVersion;
  std::string coarserNote;  // how each coarser source was made
  BenchOptions options;
  double gdalMaxSearchDistancePixels = 0;
  std::vector<std::string> methodLabels;  // column order; GDAL without smoothing is the reference
  std::string gdalReferenceLabel;
  std::string interpolationLabel;  // the method whose border range is checked
  std::vector<TileReport> tiles;
  unsigned hardwareThreads = 0;
  double totalSeconds = 0;
};

std::string markdownReport(const ReportInput& input);

}  // namespace globe::bench_fill
