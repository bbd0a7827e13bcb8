// Streams tiles of one payload kind from a tile source into a tile cache in the background:
// prioritised, cancellable, at most K load tasks at once (a task loads one tile, or the tiles its
// source reads in one request), failures reported once. TileLoader is the
// one for height blocks; imagery layers use the same class over their own payload.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "core/task_runner.hpp"
#include "geo/tile_id.hpp"
#include "streaming/block_cache.hpp"
#include "streaming/completion_queue.hpp"
#include "streaming/load_request.hpp"
#include "streaming/tile_cache.hpp"
#include "streaming/tile_source.hpp"
#include "terrain/height_block.hpp"

namespace globe::streaming {

enum class TileState {
  NotRequested,  // never asked for, cancelled, or loaded once and since evicted
  Pending,       // wanted, waiting for a free load slot
  Loading,       // started, not yet collected by poll()
  Resident,      // in the cache
  Absent,        // the source has no such tile (beyond its coverage); never retried
  Failed,        // its load failed (reported once); not retried until forgetFailures()
};

struct LoadError {
  geo::TileId tile;
  std::filesystem::path file;  // where the tile lives (TileSource::location)
  std::string message;         // names the file and what went wrong
};

struct LoaderCounters {
  uint64_t requested = 0;    // tiles newly queued (not already queued, loading, resident or known)
  uint64_t started = 0;      // loads handed to the runner
  uint64_t completed = 0;    // loads whose payload went into the cache
  uint64_t absent = 0;       // loads that found no such tile in the source
  uint64_t failed = 0;       // loads that failed
  uint64_t cancelled = 0;    // queued tiles dropped because a later request() no longer wanted them
  size_t pending = 0;        // queued, not started
  size_t inFlight = 0;       // started, not yet collected by poll()
  size_t tasksInFlight = 0;  // their tasks; at most maxInFlight()
  uint64_t readTogether = 0;  // loads started in another tile's task (TileSource::readableWith)
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
// only the thread-safe TileSource and the loader's mutex-protected CompletionQueue.
//
// Lifetime: the source must outlive the loader. The loader may go before the runner: its
// destructor waits for the loads already running, and loads that start later do nothing. A
// runner that drops tasks (ThreadPoolRunner::shutdown) leaves their tiles Loading.
template <class Payload>
class PayloadLoader {
 public:
  static constexpr size_t kDefaultMaxInFlight = 4;
  // How many of the queued tiles after the next one a source is offered to read with it.
  static constexpr size_t kReadTogetherCandidates = 256;

  PayloadLoader(TileSource<Payload>& source, core::TaskRunner& runner, TileCache<Payload>& cache)
      : source_(source),
        runner_(runner),
        cache_(cache),
        completions_(std::make_shared<CompletionQueue<Payload>>()) {}
  ~PayloadLoader() { completions_->close(); }
  PayloadLoader(const PayloadLoader&) = delete;
  PayloadLoader& operator=(const PayloadLoader&) = delete;

  // Replaces the wanted set, then starts loads up to maxInFlight(), highest priority first
  // (ties in request order; a tile listed twice keeps its higher priority). Queued tiles that
  // are no longer wanted are cancelled; loads already started complete and are cached but
  // keep no priority. Tiles resident, loading, absent or failed are not queued.
  void request(std::span<const LoadRequest> requests);
  // Moves the finished loads into the cache, records failures, starts queued loads in the
  // freed slots, and reports what arrived. Call once per frame.
  PollResult poll();

  bool isResident(const geo::TileId& tile) const { return cache_.contains(tile); }
  // The payload or null; counts a cache hit or miss.
  std::shared_ptr<const Payload> get(const geo::TileId& tile) { return cache_.get(tile); }
  TileState state(const geo::TileId& tile) const {
    if (cache_.contains(tile)) return TileState::Resident;
    if (loading_.contains(tile)) return TileState::Loading;
    if (pending_.contains(tile)) return TileState::Pending;
    if (failed_.contains(tile)) return TileState::Failed;
    if (absent_.contains(tile)) return TileState::Absent;
    return TileState::NotRequested;
  }

  size_t maxInFlight() const { return maxInFlight_; }
  // At least 1. Lowering it cancels nothing: slots free up as loads finish.
  void setMaxInFlight(size_t loads) {
    maxInFlight_ = std::max<size_t>(1, loads);
    startLoads();
  }

  // Every failure so far, in the order poll() collected them.
  const std::vector<LoadError>& errors() const { return errors_; }
  // Lets failed tiles be queued again and their source files reopened (say, after a repair).
  void forgetFailures() {
    failed_.clear();
    source_.forgetSourceFailures();
  }

  LoaderCounters counters() const {
    LoaderCounters counters = counters_;
    counters.pending = pending_.size();
    counters.inFlight = loading_.size();
    counters.tasksInFlight = tasksInFlight_;
    return counters;
  }
  // Blocks until a load has finished on its worker (ready for poll()) or the timeout passes.
  bool waitForCompletion(std::chrono::milliseconds timeout) const {
    return completions_->waitForFinished(timeout);
  }

 private:
  using Clock = std::chrono::steady_clock;
  using Finished = FinishedLoad<Payload>;

  void startLoads();
  static Finished loadTile(TileSource<Payload>& source, const geo::TileId& tile,
                           Clock::time_point postedAt);
  static std::vector<Finished> loadGroup(TileSource<Payload>& source,
                                         const std::vector<geo::TileId>& tiles,
                                         Clock::time_point postedAt);
  static Finished finished(const geo::TileId& tile, Result<std::optional<Payload>> loaded,
                           Clock::time_point postedAt);

  TileSource<Payload>& source_;
  core::TaskRunner& runner_;
  TileCache<Payload>& cache_;
  std::shared_ptr<CompletionQueue<Payload>> completions_;
  size_t maxInFlight_ = kDefaultMaxInFlight;
  std::vector<LoadRequest> queue_;  // highest priority first; queue_[nextQueued_..] are pending
  size_t nextQueued_ = 0;
  size_t tasksInFlight_ = 0;
  std::unordered_set<geo::TileId> pending_;  // the tiles of queue_[nextQueued_..]
  std::unordered_set<geo::TileId> loading_;
  std::unordered_set<geo::TileId> absent_;
  std::unordered_set<geo::TileId> failed_;
  std::vector<LoadError> errors_;
  LoaderCounters counters_;
};

template <class Payload>
FinishedLoad<Payload> PayloadLoader<Payload>::finished(const geo::TileId& tile,
                                                       Result<std::optional<Payload>> loaded,
                                                       Clock::time_point postedAt) {
  Finished done{tile, Finished::Outcome::Failed, nullptr, {}, postedAt, {}};
  if (!loaded) {
    // Named once: the source's message may name the tile already.
    const std::string name = geo::tileName(tile);
    done.error = loaded.error().find(name) != std::string::npos ? loaded.error()
                                                                 : name + ": " + loaded.error();
  } else if (!*loaded) {
    done.outcome = Finished::Outcome::Absent;
  } else {
    done.outcome = Finished::Outcome::Loaded;
    done.payload = std::make_shared<const Payload>(std::move(**loaded));
  }
  done.finishedAt = Clock::now();
  return done;
}

// Runs on a worker.
template <class Payload>
FinishedLoad<Payload> PayloadLoader<Payload>::loadTile(TileSource<Payload>& source,
                                                       const geo::TileId& tile,
                                                       Clock::time_point postedAt) {
  return finished(tile, source.load(tile), postedAt);
}

// Runs on a worker: tiles the source reads together, the last one ending the task.
template <class Payload>
std::vector<FinishedLoad<Payload>> PayloadLoader<Payload>::loadGroup(
    TileSource<Payload>& source, const std::vector<geo::TileId>& tiles,
    Clock::time_point postedAt) {
  std::vector<Result<std::optional<Payload>>> loaded = source.loadTogether(tiles);
  std::vector<Finished> done;
  done.reserve(tiles.size());
  for (size_t i = 0; i < tiles.size(); ++i) {
    done.push_back(finished(
        tiles[i],
        i < loaded.size() ? std::move(loaded[i])
                          : Result<std::optional<Payload>>(makeError("not loaded with its group")),
        postedAt));
    done.back().endsTask = false;
  }
  if (!done.empty()) done.back().endsTask = true;
  return done;
}

template <class Payload>
void PayloadLoader<Payload>::request(std::span<const LoadRequest> requests) {
  std::vector<LoadRequest> wanted;
  std::unordered_map<geo::TileId, size_t> position;  // index in `wanted`, to merge duplicates
  wanted.reserve(requests.size());
  for (const LoadRequest& r : requests) {
    const double priority =
        std::isnan(r.priority) ? -std::numeric_limits<double>::infinity() : r.priority;
    if (auto it = position.find(r.tile); it != position.end()) {
      wanted[it->second].priority = std::max(wanted[it->second].priority, priority);
      continue;
    }
    if (cache_.contains(r.tile) || loading_.contains(r.tile) || absent_.contains(r.tile) ||
        failed_.contains(r.tile)) {
      continue;
    }
    position.emplace(r.tile, wanted.size());
    wanted.push_back({r.tile, priority});
  }

  for (const geo::TileId& tile : pending_) {
    if (!position.contains(tile)) ++counters_.cancelled;
  }
  for (const LoadRequest& r : wanted) {
    if (!pending_.contains(r.tile)) ++counters_.requested;
  }
  std::stable_sort(wanted.begin(), wanted.end(), [](const LoadRequest& a, const LoadRequest& b) {
    return a.priority > b.priority;
  });
  queue_ = std::move(wanted);
  nextQueued_ = 0;
  pending_.clear();
  for (const LoadRequest& r : queue_) pending_.insert(r.tile);
  startLoads();
}

template <class Payload>
void PayloadLoader<Payload>::startLoads() {
  while (tasksInFlight_ < maxInFlight_ && nextQueued_ < queue_.size()) {
    const geo::TileId tile = queue_[nextQueued_++].tile;
    if (!pending_.contains(tile)) continue;  // already started with another tile
    pending_.erase(tile);
    loading_.insert(tile);
    std::vector<geo::TileId> group{tile};
    std::vector<geo::TileId> candidates;
    for (size_t i = nextQueued_; i < queue_.size() && candidates.size() < kReadTogetherCandidates;
         ++i) {
      if (pending_.contains(queue_[i].tile)) candidates.push_back(queue_[i].tile);
    }
    if (!candidates.empty()) {
      for (const geo::TileId& other : source_.readableWith(tile, candidates)) {
        if (pending_.erase(other) == 0) continue;  // not a candidate: ignored
        loading_.insert(other);
        group.push_back(other);
        ++counters_.readTogether;
      }
    }
    counters_.started += group.size();
    ++tasksInFlight_;
    const Clock::time_point postedAt = Clock::now();
    if (group.size() == 1) {
      runner_.post([completions = completions_, source = &source_, tile, postedAt] {
        if (!completions->begin()) return;  // the loader is gone
        completions->finish(loadTile(*source, tile, postedAt));
      });
    } else {
      runner_.post(
          [completions = completions_, source = &source_, group = std::move(group), postedAt] {
            if (!completions->begin()) return;
            completions->finishAll(loadGroup(*source, group, postedAt));
          });
    }
  }
}

template <class Payload>
PollResult PayloadLoader<Payload>::poll() {
  PollResult result;
  const Clock::time_point now = Clock::now();
  const auto seconds = [](Clock::time_point from, Clock::time_point to) {
    return std::chrono::duration<double>(to - from).count();
  };
  for (Finished& done : completions_->takeAll()) {
    loading_.erase(done.tile);
    if (done.endsTask && tasksInFlight_ > 0) --tasksInFlight_;
    switch (done.outcome) {
      case Finished::Outcome::Loaded:
        cache_.insert(done.tile, std::move(done.payload));
        ++counters_.completed;
        result.arrived.push_back(
            {done.tile, seconds(done.postedAt, done.finishedAt), seconds(done.postedAt, now)});
        break;
      case Finished::Outcome::Absent:
        absent_.insert(done.tile);
        ++counters_.absent;
        break;
      case Finished::Outcome::Failed: {
        failed_.insert(done.tile);
        ++counters_.failed;
        LoadError error{done.tile, source_.location(done.tile), std::move(done.error)};
        errors_.push_back(error);
        result.errors.push_back(std::move(error));
        break;
      }
    }
  }
  startLoads();
  return result;
}

using TileLoader = PayloadLoader<terrain::HeightBlock>;
extern template class PayloadLoader<terrain::HeightBlock>;

}  // namespace globe::streaming
