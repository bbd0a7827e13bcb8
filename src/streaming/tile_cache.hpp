// Resident tiles of one payload kind: an LRU cache under a byte budget, in which the tiles of the
// current frame are pinned so that eviction never takes one the viewer is drawing.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "geo/tile_id.hpp"
#include "streaming/tile_source.hpp"

namespace globe::streaming {

struct TileCacheCounters {
  uint64_t hits = 0;       // get() found the payload
  uint64_t misses = 0;     // get() did not
  uint64_t loads = 0;      // payloads inserted
  uint64_t evictions = 0;  // payloads evicted to get back within the budget
  size_t entries = 0;
  size_t residentBytes = 0;  // entryBytes() summed over the entries
  size_t peakResidentBytes = 0;
  size_t pinnedBytes = 0;  // of the entries pinned in the current frame
  size_t peakPinnedBytes = 0;
};

// Pinning and eviction. A fresh cache is in its first frame; beginFrame() starts the next one
// and so releases every pin. An entry is pinned for the rest of the current frame when it is
// touched or inserted in it (inserted: poll() reports it as arrived, so it must still be there
// when the viewer asks for it). Whenever insert() or setBudgetBytes() leaves residentBytes above
// the budget, the least recently used UNPINNED entries are evicted until it is within budget
// or only pinned entries remain. So after each of those calls
//     residentBytes <= max(budgetBytes, pinnedBytes),
// i.e. the budget is exceeded only when the frame's pinned tiles alone exceed it, and then by
// no unpinned byte; peakResidentBytes <= max(budgetBytes, peakPinnedBytes) always. beginFrame()
// itself evicts nothing: last frame's tiles are about to be touched again.
//
// Recency: insert(), touch() and get() make an entry the most recent; contains() does not.
// Not thread-safe: the main thread owns it. Payloads are shared, so one still held by a caller
// outlives its eviction (it then no longer counts as resident).
template <class Payload>
class TileCache {
 public:
  // Per entry, besides the payload's own bytes: the LRU list node (~80 B with its allocation
  // header), the hash index node and bucket (~56 B), the shared payload's control block and
  // object (~64 B) and its buffer's allocation header (~16 B), as libstdc++ lays them out on
  // x86-64.
  static constexpr size_t kEntryOverheadBytes = 224;
  static size_t entryBytes(const Payload& payload) {
    return PayloadBytes<Payload>::of(payload) + kEntryOverheadBytes;
  }

  explicit TileCache(size_t budgetBytes) : budgetBytes_(budgetBytes) {}

  size_t budgetBytes() const { return budgetBytes_; }
  // Evicts unpinned entries at once if the new budget is exceeded.
  void setBudgetBytes(size_t budgetBytes) {
    budgetBytes_ = budgetBytes;
    evictToBudget();
  }

  // Starts a new frame: the previous frame's pins are released.
  void beginFrame() {
    ++frame_;
    counters_.pinnedBytes = 0;
  }
  // Pins the resident tiles among these (the frame's rendering tile array) and makes them the
  // most recent; returns how many were resident. Tiles not resident are ignored.
  size_t touch(std::span<const geo::TileId> tiles) {
    size_t resident = 0;
    for (const geo::TileId& tile : tiles) {
      auto it = index_.find(tile);
      if (it == index_.end()) continue;
      lru_.splice(lru_.begin(), lru_, it->second);
      pin(*it->second);
      ++resident;
    }
    return resident;
  }

  // Adds or replaces a payload as the most recent entry, pinned in this frame; null is ignored.
  void insert(const geo::TileId& tile, std::shared_ptr<const Payload> payload);
  // The payload or null, counting a hit or a miss.
  std::shared_ptr<const Payload> get(const geo::TileId& tile) {
    auto it = index_.find(tile);
    if (it == index_.end()) {
      ++counters_.misses;
      return nullptr;
    }
    ++counters_.hits;
    lru_.splice(lru_.begin(), lru_, it->second);
    return it->second->payload;
  }
  bool contains(const geo::TileId& tile) const { return index_.contains(tile); }
  bool isPinned(const geo::TileId& tile) const {
    auto it = index_.find(tile);
    return it != index_.end() && it->second->pinnedFrame == frame_;
  }
  // Resident tiles, most recently used first (the last is the next to be evicted if unpinned).
  std::vector<geo::TileId> tilesByRecency() const {
    std::vector<geo::TileId> tiles;
    tiles.reserve(lru_.size());
    for (const Entry& entry : lru_) tiles.push_back(entry.tile);
    return tiles;
  }

  const TileCacheCounters& counters() const { return counters_; }

 private:
  struct Entry {
    geo::TileId tile;
    std::shared_ptr<const Payload> payload;
    size_t bytes;
    uint64_t pinnedFrame;  // pinned while this equals frame_
  };
  using Lru = std::list<Entry>;  // most recent first

  void pin(Entry& entry) {
    if (entry.pinnedFrame == frame_) return;
    entry.pinnedFrame = frame_;
    counters_.pinnedBytes += entry.bytes;
    counters_.peakPinnedBytes = std::max(counters_.peakPinnedBytes, counters_.pinnedBytes);
  }
  void evictToBudget();

  size_t budgetBytes_;
  uint64_t frame_ = 1;
  Lru lru_;
  std::unordered_map<geo::TileId, typename Lru::iterator> index_;
  TileCacheCounters counters_;
};

template <class Payload>
void TileCache<Payload>::insert(const geo::TileId& tile, std::shared_ptr<const Payload> payload) {
  if (!payload) return;
  const size_t bytes = entryBytes(*payload);
  if (auto it = index_.find(tile); it != index_.end()) {
    Entry& entry = *it->second;
    counters_.residentBytes -= entry.bytes;
    if (entry.pinnedFrame == frame_) counters_.pinnedBytes -= entry.bytes;
    entry.payload = std::move(payload);
    entry.bytes = bytes;
    entry.pinnedFrame = 0;  // re-pinned below with the new size
    lru_.splice(lru_.begin(), lru_, it->second);
  } else {
    lru_.push_front(Entry{tile, std::move(payload), bytes, 0});
    index_.emplace(tile, lru_.begin());
    ++counters_.entries;
  }
  ++counters_.loads;
  counters_.residentBytes += bytes;
  pin(lru_.front());
  // Evict before recording the peak: the peak is what survives the call, bounded by the rule.
  evictToBudget();
  counters_.peakResidentBytes = std::max(counters_.peakResidentBytes, counters_.residentBytes);
}

template <class Payload>
void TileCache<Payload>::evictToBudget() {
  // From the least recent end; pinned entries are stepped over, not evicted. They cluster at
  // the recent end (touch and insert move them there), so the walk rarely visits them.
  auto it = lru_.end();
  while (counters_.residentBytes > budgetBytes_ && it != lru_.begin()) {
    --it;
    if (it->pinnedFrame == frame_) continue;
    counters_.residentBytes -= it->bytes;
    index_.erase(it->tile);
    it = lru_.erase(it);
    --counters_.entries;
    ++counters_.evictions;
  }
}

}  // namespace globe::streaming
