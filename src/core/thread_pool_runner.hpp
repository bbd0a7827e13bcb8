// A task runner backed by a fixed set of worker threads sharing one FIFO queue.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "core/task_runner.hpp"

namespace globe::core {

// Shutdown is deterministic: queued tasks that have not started are dropped (destroyed
// unrun, releasing what they captured), tasks already running finish, and the workers are
// joined. Tasks posted after shutdown are dropped too.
class ThreadPoolRunner final : public TaskRunner {
 public:
  explicit ThreadPoolRunner(unsigned threads);  // at least one worker, even for 0
  ~ThreadPoolRunner() override;
  ThreadPoolRunner(const ThreadPoolRunner&) = delete;
  ThreadPoolRunner& operator=(const ThreadPoolRunner&) = delete;

  void post(std::function<void()> task) override;
  // Returns how many tasks were dropped by this call; later calls do nothing and return 0.
  // Must not be called from one of the runner's own tasks (it joins their threads).
  size_t shutdown();
  size_t threadCount() const { return workers_.size(); }
  // Tasks posted and not yet taken by a worker.
  size_t queued() const;

 private:
  void work();

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> tasks_;
  bool stopping_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace globe::core
