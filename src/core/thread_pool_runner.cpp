#include "core/thread_pool_runner.hpp"

#include <algorithm>
#include <utility>

namespace globe::core {

ThreadPoolRunner::ThreadPoolRunner(unsigned threads) {
  const unsigned count = std::max(1U, threads);
  workers_.reserve(count);
  for (unsigned i = 0; i < count; ++i) workers_.emplace_back([this] { work(); });
}

ThreadPoolRunner::~ThreadPoolRunner() { shutdown(); }

void ThreadPoolRunner::post(std::function<void()> task) {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return;  // dropped: the task is destroyed, unrun, as this call returns
    tasks_.push_back(std::move(task));
  }
  wake_.notify_one();
}

size_t ThreadPoolRunner::shutdown() {
  std::deque<std::function<void()>> dropped;
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return 0;
    stopping_ = true;
    dropped.swap(tasks_);
  }
  wake_.notify_all();
  for (std::thread& worker : workers_) worker.join();
  // Destroyed after the lock is released: a captured object's destructor may post or lock.
  return dropped.size();
}

size_t ThreadPoolRunner::queued() const {
  std::lock_guard lock(mutex_);
  return tasks_.size();
}

void ThreadPoolRunner::work() {
  for (;;) {
    std::function<void()> task;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !tasks_.empty(); });
      if (stopping_) return;
      task = std::move(tasks_.front());
      tasks_.pop_front();
    }
    task();
  }
}

}  // namespace globe::core
