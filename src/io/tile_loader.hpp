// Streams height blocks from the tile store into the block cache in the background:
// prioritised, cancellable, at most K loads at once, failures reported once.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <unordered_set>
#include <vector>

#include "geo/tile_id.hpp"
#include "io/block_cache.hpp"
#include "io/completion_queue.hpp"
#include "io/load_request.hpp"
#include "io/task_runner.hpp"
#include "io/tile_store.hpp"
#include "terrain/height_block.hpp"

namespace globe::io {

enum class TileState {
  NotRequested,  // never asked for, cancelled, or loaded once and since evicted
  Pending,       // wanted, waiting for a free load slot
  Loading,       // started, not yet collected by poll()
  Resident,      // in the cache
  Absent,        // the pyramid has no such tile (beyond its coverage); never retried
  Failed,        // its load failed (reported once); not retried until forgetFailures()
};

struct LoadError {
  geo::TileId tile;
  std::filesystem::path file;  // the pack the block lives in
  std::string message;         // names the file and what went wrong
};

struct LoaderCounters {
  uint64_t requested = 0;  // tiles newly queued (not already queued, loading, resident or known)
  uint64_t started = 0;    // loads handed to the runner
  uint64_t completed = 0;  // loads whose block went into the cache
  uint64_t absent = 0;     // loads that found no such tile in the pyramid
  uint64_t failed = 0;     // loads that failed
  uint64_t cancelled = 0;  // queued tiles dropped because a later request() no longer wanted them
  size_t pending = 0;      // queued, not started
  size_t inFlight = 0;     // started, not yet collected by poll(); at most maxInFlight()
};

struct PollResult {
  struct Arrival {
    geo::TileId tile;
    double workerLatencySeconds;   // from the load's start (post) to its end on the worker
    double visibleLatencySeconds;  // from the load's start to this poll()
  };
  std::vector<Arrival> arrived;   // now resident (and pinned in the cache's current frame)
  std::vector<LoadError> errors;  // loads that failed since the last poll: each tile once
};

// One frame on the main thread:
//   cache.beginFrame();          // releases last frame's pins
//   ...select the rendering tile array from what isResident()...
//   cache.touch(array);          // pins what is drawn this frame
//   loader.request(wanted);      // replaces the wanted set
//   auto result = loader.poll(); // redraw next frame if result.arrived is not empty
// request, poll, get, isResident and state are for the main thread only. Load tasks touch
// only the thread-safe TileStore and the loader's mutex-protected CompletionQueue.
//
// Lifetime: the store must outlive the loader. The loader may go before the runner: its
// destructor waits for the loads already running, and loads that start later do nothing. A
// runner that drops tasks (ThreadPoolRunner::shutdown) leaves their tiles Loading.
class TileLoader {
 public:
  static constexpr size_t kDefaultMaxInFlight = 4;

  TileLoader(TileStore& store, TaskRunner& runner, BlockCache& cache);
  ~TileLoader();
  TileLoader(const TileLoader&) = delete;
  TileLoader& operator=(const TileLoader&) = delete;

  // Replaces the wanted set, then starts loads up to maxInFlight(), highest priority first
  // (ties in request order; a tile listed twice keeps its higher priority). Queued tiles that
  // are no longer wanted are cancelled; loads already started complete and are cached but
  // keep no priority. Tiles resident, loading, absent or failed are not queued.
  void request(std::span<const LoadRequest> requests);
  // Moves the finished loads into the cache, records failures, starts queued loads in the
  // freed slots, and reports what arrived. Call once per frame.
  PollResult poll();

  bool isResident(const geo::TileId& tile) const { return cache_.contains(tile); }
  // The block or null; counts a cache hit or miss.
  std::shared_ptr<const terrain::HeightBlock> get(const geo::TileId& tile) {
    return cache_.get(tile);
  }
  TileState state(const geo::TileId& tile) const;

  size_t maxInFlight() const { return maxInFlight_; }
  // At least 1. Lowering it cancels nothing: slots free up as loads finish.
  void setMaxInFlight(size_t loads);

  // Every failure so far, in the order poll() collected them.
  const std::vector<LoadError>& errors() const { return errors_; }
  // Lets failed tiles be queued again and their packs reopened (say, after a repair).
  void forgetFailures() {
    failed_.clear();
    store_.forgetFailedPacks();
  }

  LoaderCounters counters() const;
  // Blocks until a load has finished on its worker (ready for poll()) or the timeout passes.
  bool waitForCompletion(std::chrono::milliseconds timeout) const {
    return completions_->waitForFinished(timeout);
  }

 private:
  void startLoads();

  TileStore& store_;
  TaskRunner& runner_;
  BlockCache& cache_;
  std::shared_ptr<CompletionQueue> completions_;
  size_t maxInFlight_ = kDefaultMaxInFlight;
  std::vector<LoadRequest> queue_;  // highest priority first; queue_[nextQueued_..] are pending
  size_t nextQueued_ = 0;
  std::unordered_set<geo::TileId> pending_;  // the tiles of queue_[nextQueued_..]
  std::unordered_set<geo::TileId> loading_;
  std::unordered_set<geo::TileId> absent_;
  std::unordered_set<geo::TileId> failed_;
  std::vector<LoadError> errors_;
  LoaderCounters counters_;
};

}  // namespace globe::io
