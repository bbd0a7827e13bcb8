// The window's copy of what goes to stderr: the latest warning (a server failing, a damaged
// pack) kept for the HUD for a while, so a user who never sees the terminal sees it too. The
// scene's loader threads warn through it: thread-safe.
#pragma once

#include <chrono>
#include <memory>
#include <mutex>
#include <string>

#include "core/warnings.hpp"

namespace globe::app {

class RecentWarning {
 public:
  static constexpr std::chrono::seconds kShownFor{15};

  // A sink that passes each warning on to `next` (stderr) and keeps it.
  static core::WarningSink wrap(core::WarningSink next,
                                const std::shared_ptr<RecentWarning>& kept) {
    return [next = std::move(next), kept](const std::string& warning) {
      if (next) next(warning);
      const std::lock_guard lock(kept->mutex_);
      kept->text_ = warning;
      kept->at_ = std::chrono::steady_clock::now();
      ++kept->count_;
    };
  }
  // The latest warning while it is recent, else empty.
  std::string shown() const {
    const std::lock_guard lock(mutex_);
    if (text_.empty() || std::chrono::steady_clock::now() - at_ > kShownFor) return {};
    return text_;
  }
  // Warnings so far: a change means the HUD has something new to draw.
  size_t count() const {
    const std::lock_guard lock(mutex_);
    return count_;
  }

 private:
  mutable std::mutex mutex_;
  std::string text_;
  std::chrono::steady_clock::time_point at_;
  size_t count_ = 0;
};

}  // namespace globe::app
