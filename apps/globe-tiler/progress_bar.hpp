// globe-tiler's one-line progress bar with rate and ETA, redrawn in place on a terminal.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

#include "tiling/progress.hpp"

namespace globe::tiler_app {

class ProgressBar {
 public:
  // Draws on `out` only when `enabled` (the program passes "not --quiet and stderr is a tty").
  explicit ProgressBar(bool enabled, std::FILE* out = stderr);
  // Redraws at most a few times a second; the finished report always, then a newline.
  void report(const tiling::Progress& progress);
  // What a run's options take.
  tiling::ProgressSink sink() {
    return [this](const tiling::Progress& p) { report(p); };
  }

 private:
  void draw(const tiling::Progress& progress);

  bool enabled_;
  std::FILE* out_;
  bool started_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastDraw_;
};

// "1:02:03" / "02:03"
std::string formatDuration(double seconds);

}  // namespace globe::tiler_app
