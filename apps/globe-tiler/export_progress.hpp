// What `globe-tiler export` says while a tree is made: the run's size as it starts, its expected
// time once the first tiles show the rate, and a bar on a terminal.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "apps/globe-tiler/progress_bar.hpp"
#include "publish/export_writes.hpp"

namespace globe::tiler_app {

class ExportProgressPrinter {
 public:
  ExportProgressPrinter(std::string format, unsigned threads, bool quiet, bool bar);
  // What the exporter calls: (0, total) first, then as tiles finish.
  publish::ExportProgress sink() {
    return [this](uint64_t done, uint64_t total) { report(done, total); };
  }
  void finish();

 private:
  void report(uint64_t done, uint64_t total);

  std::string format_;
  unsigned threads_;
  bool quiet_;
  ProgressBar bar_;
  bool planned_ = false, estimated_ = false;
  uint64_t done_ = 0, total_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace globe::tiler_app
