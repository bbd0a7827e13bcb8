#include "io/completion_queue.hpp"

#include <utility>

namespace globe::io {

bool CompletionQueue::begin() {
  std::lock_guard lock(mutex_);
  if (closed_) return false;
  ++running_;
  return true;
}

bool CompletionQueue::waitForFinished(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  return idle_.wait_for(lock, timeout, [&] { return !finished_.empty() || closed_; }) &&
         !finished_.empty();
}

void CompletionQueue::finish(FinishedLoad load) {
  {
    std::lock_guard lock(mutex_);
    --running_;
    // After close() nobody will collect it; dropping it here frees the block at once.
    if (!closed_) finished_.push_back(std::move(load));
  }
  idle_.notify_all();
}

std::vector<FinishedLoad> CompletionQueue::takeAll() {
  std::vector<FinishedLoad> taken;
  std::lock_guard lock(mutex_);
  taken.swap(finished_);
  return taken;
}

void CompletionQueue::close() {
  std::unique_lock lock(mutex_);
  closed_ = true;
  idle_.wait(lock, [this] { return running_ == 0; });
  finished_.clear();
}

}  // namespace globe::io
