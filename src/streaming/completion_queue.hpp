// The hand-off between load tasks on worker threads and the loader on the main thread: the
// only state they share, behind one mutex.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "geo/tile_id.hpp"

namespace globe::streaming {

template <class Payload>
struct FinishedLoad {
  enum class Outcome { Loaded, Absent, Failed };
  geo::TileId tile;
  Outcome outcome = Outcome::Failed;
  std::shared_ptr<const Payload> payload;  // when Loaded
  std::string error;                       // when Failed
  std::chrono::steady_clock::time_point postedAt;
  std::chrono::steady_clock::time_point finishedAt;
  bool endsTask = true;  // the last load of its task (a task may load tiles read together)
};

// Tasks hold it by shared_ptr, so a task that runs after its loader is gone finds it closed.
template <class Payload>
class CompletionQueue {
 public:
  // Worker side: a task calls begin() first and, only if it returns true, does its work and
  // then calls finish(). False once the queue is closed: the task must do nothing.
  bool begin() {
    std::lock_guard lock(mutex_);
    if (closed_) return false;
    ++running_;
    return true;
  }
  void finish(FinishedLoad<Payload> load) {
    {
      std::lock_guard lock(mutex_);
      --running_;
      // After close() nobody will collect it; dropping it here frees the payload at once.
      if (!closed_) finished_.push_back(std::move(load));
    }
    idle_.notify_all();
  }

  // The same for a task that loaded several tiles: all of them, once.
  void finishAll(std::vector<FinishedLoad<Payload>> loads) {
    {
      std::lock_guard lock(mutex_);
      --running_;
      if (!closed_) {
        for (FinishedLoad<Payload>& load : loads) finished_.push_back(std::move(load));
      }
    }
    idle_.notify_all();
  }

  // Main-thread side: everything finished since the last call, in finishing order.
  std::vector<FinishedLoad<Payload>> takeAll() {
    std::vector<FinishedLoad<Payload>> taken;
    std::lock_guard lock(mutex_);
    taken.swap(finished_);
    return taken;
  }
  // Blocks until a finished load waits to be taken or the timeout passes; true if one waits.
  bool waitForFinished(std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    return idle_.wait_for(lock, timeout, [&] { return !finished_.empty() || closed_; }) &&
           !finished_.empty();
  }
  // Refuses tasks that have not begun and waits for those that have to finish, so that no
  // task touches the loader's source after this returns.
  void close() {
    std::unique_lock lock(mutex_);
    closed_ = true;
    idle_.wait(lock, [this] { return running_ == 0; });
    finished_.clear();
  }

 private:
  std::mutex mutex_;
  std::condition_variable idle_;
  std::vector<FinishedLoad<Payload>> finished_;
  size_t running_ = 0;
  bool closed_ = false;
};

}  // namespace globe::streaming
