// The hand-off between load tasks on worker threads and the loader on the main thread: the
// only state they share, behind one mutex.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "geo/tile_id.hpp"
#include "terrain/height_block.hpp"

namespace globe::io {

struct FinishedLoad {
  enum class Outcome { Loaded, Absent, Failed };
  geo::TileId tile;
  Outcome outcome = Outcome::Failed;
  std::shared_ptr<const terrain::HeightBlock> block;  // when Loaded
  std::string error;                                  // when Failed
  std::chrono::steady_clock::time_point postedAt;
  std::chrono::steady_clock::time_point finishedAt;
};

// Tasks hold it by shared_ptr, so a task that runs after its loader is gone finds it closed.
class CompletionQueue {
 public:
  // Worker side: a task calls begin() first and, only if it returns true, does its work and
  // then calls finish(). False once the queue is closed: the task must do nothing.
  bool begin();
  void finish(FinishedLoad load);

  // Main-thread side: everything finished since the last call, in finishing order.
  std::vector<FinishedLoad> takeAll();
  // Blocks until a finished load waits to be taken or the timeout passes; true if one waits.
  bool waitForFinished(std::chrono::milliseconds timeout);
  // Refuses tasks that have not begun and waits for those that have to finish, so that no
  // task touches the loader's store after this returns.
  void close();

 private:
  std::mutex mutex_;
  std::condition_variable idle_;
  std::vector<FinishedLoad> finished_;
  size_t running_ = 0;
  bool closed_ = false;
};

}  // namespace globe::io
