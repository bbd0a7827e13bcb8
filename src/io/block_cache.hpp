// The resident height blocks: an LRU cache under a byte budget, in which the tiles of the
// current frame are pinned so that eviction never takes one the viewer is drawing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "geo/tile_id.hpp"
#include "terrain/height_block.hpp"

namespace globe::io {

struct BlockCacheCounters {
  uint64_t hits = 0;       // get() found the block
  uint64_t misses = 0;     // get() did not
  uint64_t loads = 0;      // blocks inserted
  uint64_t evictions = 0;  // blocks evicted to get back within the budget
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
// Not thread-safe: the main thread owns it. Blocks are shared, so a block still held by a
// caller outlives its eviction (it then no longer counts as resident).
class BlockCache {
 public:
  // Per entry, besides the samples: the LRU list node (~80 B with its allocation header), the
  // hash index node and bucket (~56 B), the shared block's control block and HeightBlock
  // (~64 B) and the samples' allocation header (~16 B), as libstdc++ lays them out on x86-64.
  static constexpr size_t kEntryOverheadBytes = 224;
  static size_t entryBytes(const terrain::HeightBlock& block);

  explicit BlockCache(size_t budgetBytes);

  size_t budgetBytes() const { return budgetBytes_; }
  // Evicts unpinned entries at once if the new budget is exceeded.
  void setBudgetBytes(size_t budgetBytes);

  // Starts a new frame: the previous frame's pins are released.
  void beginFrame();
  // Pins the resident tiles among these (the frame's rendering tile array) and makes them the
  // most recent; returns how many were resident. Tiles not resident are ignored.
  size_t touch(std::span<const geo::TileId> tiles);

  // Adds or replaces a block as the most recent entry, pinned in this frame; null is ignored.
  void insert(const geo::TileId& tile, std::shared_ptr<const terrain::HeightBlock> block);
  // The block or null, counting a hit or a miss.
  std::shared_ptr<const terrain::HeightBlock> get(const geo::TileId& tile);
  bool contains(const geo::TileId& tile) const { return index_.contains(tile); }
  bool isPinned(const geo::TileId& tile) const;
  // Resident tiles, most recently used first (the last is the next to be evicted if unpinned).
  std::vector<geo::TileId> tilesByRecency() const;

  const BlockCacheCounters& counters() const { return counters_; }

 private:
  struct Entry {
    geo::TileId tile;
    std::shared_ptr<const terrain::HeightBlock> block;
    size_t bytes;
    uint64_t pinnedFrame;  // pinned while this equals frame_
  };
  using Lru = std::list<Entry>;  // most recent first

  void pin(Entry& entry);
  void evictToBudget();

  size_t budgetBytes_;
  uint64_t frame_ = 1;
  Lru lru_;
  std::unordered_map<geo::TileId, Lru::iterator> index_;
  BlockCacheCounters counters_;
};

}  // namespace globe::io
