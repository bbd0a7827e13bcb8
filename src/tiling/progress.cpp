#include "tiling/progress.hpp"

#include <chrono>

namespace globe::tiling {

void waitForLevel(const ProgressSink& progress, std::mutex& mutex,
                  std::condition_variable& finished, const unsigned& running,
                  const std::atomic<uint64_t>& done, uint64_t total, uint32_t level,
                  uint32_t maxLevel) {
  const std::string label = "level " + std::to_string(level) + "/" + std::to_string(maxLevel);
  std::unique_lock lock(mutex);
  while (running > 0) {
    finished.wait_for(lock, std::chrono::milliseconds(100));
    lock.unlock();
    if (progress) progress({done, total, label, false});
    lock.lock();
  }
}

}  // namespace globe::tiling
