#include "tests/support/inline_runner.hpp"

#include <utility>

namespace globe::testing {

void InlineRunner::post(std::function<void()> task) { tasks_.push_back(std::move(task)); }

bool InlineRunner::runOne() {
  if (tasks_.empty()) return false;
  // Popped before running, so a task that posts more cannot invalidate what is running.
  std::function<void()> task = std::move(tasks_.front());
  tasks_.pop_front();
  task();
  return true;
}

size_t InlineRunner::runAll() {
  size_t ran = 0;
  while (runOne()) ++ran;
  return ran;
}

}  // namespace globe::testing
