// How far a tiling run is. The tilers report it; the program decides how to show it
// (globe-tiler draws a bar on a terminal).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>

namespace globe::tiling {

struct Progress {
  uint64_t tilesDone = 0;
  uint64_t tilesTotal = 0;
  std::string label;      // "level 3/9", "done"
  bool finished = false;  // the run's last report
};

// Called from the thread that runs the tiler, often (every 100 ms while a level runs): a sink
// that draws should throttle itself. Empty: no reports.
using ProgressSink = std::function<void(const Progress&)>;

// Waits until `running` (guarded by `mutex`, changes signalled on `finished`) is 0, reporting
// `done` of `total` and "level L/MAX" meanwhile: how both tilers wait for a level's workers.
void waitForLevel(const ProgressSink& progress, std::mutex& mutex,
                  std::condition_variable& finished, const unsigned& running,
                  const std::atomic<uint64_t>& done, uint64_t total, uint32_t level,
                  uint32_t maxLevel);

}  // namespace globe::tiling
