// A task runner for tests: tasks wait in a FIFO queue until the test runs them, so every
// interleaving of loads and frames is chosen by the test and reproducible.
#pragma once

#include <cstddef>
#include <deque>
#include <functional>

#include "core/task_runner.hpp"

namespace globe::testing {

// Single-threaded: post and run from the same thread. Tasks may post further tasks.
class InlineRunner final : public core::TaskRunner {
 public:
  void post(std::function<void()> task) override;

  // Runs the oldest queued task; false when the queue was empty.
  bool runOne();
  // Runs queued tasks (including those they post) until none is left; returns how many ran.
  size_t runAll();
  size_t queued() const { return tasks_.size(); }

 private:
  std::deque<std::function<void()>> tasks_;
};

}  // namespace globe::testing
