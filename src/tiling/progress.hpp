// A one-line progress bar with rate and ETA, redrawn in place on a terminal.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>

namespace globe::tiling {

class ProgressBar {
 public:
  ProgressBar(uint64_t total, bool enabled, std::FILE* out = stderr);
  // Redraws at most a few times a second; call as often as you like.
  void update(uint64_t done, const std::string& label);
  void finish(uint64_t done, const std::string& label);

 private:
  void draw(uint64_t done, const std::string& label);

  uint64_t total_;
  bool enabled_;
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastDraw_;
};

// Waits until `running` (guarded by `mutex`, changes signalled on `finished`) is 0, redrawing the
// bar with `done` and "level L/MAX" meanwhile: how both tilers wait for a level's workers.
void waitForLevel(ProgressBar& progress, std::mutex& mutex, std::condition_variable& finished,
                  const unsigned& running, const std::atomic<uint64_t>& done, uint32_t level,
                  uint32_t maxLevel);

// "1:02:03" / "02:03"
std::string formatDuration(double seconds);

}  // namespace globe::tiling
