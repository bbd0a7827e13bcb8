#include "io/tile_loader.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

namespace globe::io {
namespace {

using Clock = std::chrono::steady_clock;

double secondsBetween(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

std::string tileName(const geo::TileId& tile) {
  return "tile " + std::to_string(tile.level) + "/" + std::to_string(tile.x) + "/" +
         std::to_string(tile.y);
}

// Runs on a worker: the tile's index entry first, so that a tile beyond the pyramid's coverage
// is told apart from a pack that is missing or damaged.
FinishedLoad loadTile(TileStore& store, const geo::TileId& tile, Clock::time_point postedAt) {
  FinishedLoad done{tile, FinishedLoad::Outcome::Failed, nullptr, {}, postedAt, {}};
  auto entry = store.entry(tile);
  if (!entry) {
    done.error = tileName(tile) + ": " + entry.error();
  } else if (!*entry) {
    done.outcome = FinishedLoad::Outcome::Absent;
  } else if (auto block = store.loadBlock(tile); !block) {
    done.error = tileName(tile) + ": " + block.error();
  } else {
    done.outcome = FinishedLoad::Outcome::Loaded;
    done.block = std::make_shared<const terrain::HeightBlock>(std::move(*block));
  }
  done.finishedAt = Clock::now();
  return done;
}

}  // namespace

TileLoader::TileLoader(TileStore& store, TaskRunner& runner, BlockCache& cache)
    : store_(store),
      runner_(runner),
      cache_(cache),
      completions_(std::make_shared<CompletionQueue>()) {}

TileLoader::~TileLoader() { completions_->close(); }

void TileLoader::request(std::span<const LoadRequest> requests) {
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

void TileLoader::startLoads() {
  while (loading_.size() < maxInFlight_ && nextQueued_ < queue_.size()) {
    const geo::TileId tile = queue_[nextQueued_++].tile;
    pending_.erase(tile);
    loading_.insert(tile);
    ++counters_.started;
    runner_.post([completions = completions_, store = &store_, tile, postedAt = Clock::now()] {
      if (!completions->begin()) return;  // the loader is gone
      completions->finish(loadTile(*store, tile, postedAt));
    });
  }
}

PollResult TileLoader::poll() {
  PollResult result;
  const Clock::time_point now = Clock::now();
  for (FinishedLoad& done : completions_->takeAll()) {
    loading_.erase(done.tile);
    switch (done.outcome) {
      case FinishedLoad::Outcome::Loaded:
        cache_.insert(done.tile, std::move(done.block));
        ++counters_.completed;
        result.arrived.push_back({done.tile, secondsBetween(done.postedAt, done.finishedAt),
                                  secondsBetween(done.postedAt, now)});
        break;
      case FinishedLoad::Outcome::Absent:
        absent_.insert(done.tile);
        ++counters_.absent;
        break;
      case FinishedLoad::Outcome::Failed: {
        failed_.insert(done.tile);
        ++counters_.failed;
        const PackId pack = packOf(done.tile, store_.manifest().packTilesPerSide);
        LoadError error{done.tile, packPath(store_.directory(), pack), std::move(done.error)};
        errors_.push_back(error);
        result.errors.push_back(std::move(error));
        break;
      }
    }
  }
  startLoads();
  return result;
}

TileState TileLoader::state(const geo::TileId& tile) const {
  if (cache_.contains(tile)) return TileState::Resident;
  if (loading_.contains(tile)) return TileState::Loading;
  if (pending_.contains(tile)) return TileState::Pending;
  if (failed_.contains(tile)) return TileState::Failed;
  if (absent_.contains(tile)) return TileState::Absent;
  return TileState::NotRequested;
}

void TileLoader::setMaxInFlight(size_t loads) {
  maxInFlight_ = std::max<size_t>(1, loads);
  startLoads();
}

LoaderCounters TileLoader::counters() const {
  LoaderCounters counters = counters_;
  counters.pending = pending_.size();
  counters.inFlight = loading_.size();
  return counters;
}

}  // namespace globe::io
