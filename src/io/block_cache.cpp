#include "io/block_cache.hpp"

#include <algorithm>
#include <utility>

namespace globe::io {

size_t BlockCache::entryBytes(const terrain::HeightBlock& block) {
  return block.heights.size() * sizeof(int16_t) + kEntryOverheadBytes;
}

BlockCache::BlockCache(size_t budgetBytes) : budgetBytes_(budgetBytes) {}

void BlockCache::setBudgetBytes(size_t budgetBytes) {
  budgetBytes_ = budgetBytes;
  evictToBudget();
}

void BlockCache::beginFrame() {
  ++frame_;
  counters_.pinnedBytes = 0;
}

void BlockCache::pin(Entry& entry) {
  if (entry.pinnedFrame == frame_) return;
  entry.pinnedFrame = frame_;
  counters_.pinnedBytes += entry.bytes;
  counters_.peakPinnedBytes = std::max(counters_.peakPinnedBytes, counters_.pinnedBytes);
}

size_t BlockCache::touch(std::span<const geo::TileId> tiles) {
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

void BlockCache::insert(const geo::TileId& tile,
                        std::shared_ptr<const terrain::HeightBlock> block) {
  if (!block) return;
  const size_t bytes = entryBytes(*block);
  if (auto it = index_.find(tile); it != index_.end()) {
    Entry& entry = *it->second;
    counters_.residentBytes -= entry.bytes;
    if (entry.pinnedFrame == frame_) counters_.pinnedBytes -= entry.bytes;
    entry.block = std::move(block);
    entry.bytes = bytes;
    entry.pinnedFrame = 0;  // re-pinned below with the new size
    lru_.splice(lru_.begin(), lru_, it->second);
  } else {
    lru_.push_front(Entry{tile, std::move(block), bytes, 0});
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

std::shared_ptr<const terrain::HeightBlock> BlockCache::get(const geo::TileId& tile) {
  auto it = index_.find(tile);
  if (it == index_.end()) {
    ++counters_.misses;
    return nullptr;
  }
  ++counters_.hits;
  lru_.splice(lru_.begin(), lru_, it->second);
  return it->second->block;
}

bool BlockCache::isPinned(const geo::TileId& tile) const {
  auto it = index_.find(tile);
  return it != index_.end() && it->second->pinnedFrame == frame_;
}

std::vector<geo::TileId> BlockCache::tilesByRecency() const {
  std::vector<geo::TileId> tiles;
  tiles.reserve(lru_.size());
  for (const Entry& entry : lru_) tiles.push_back(entry.tile);
  return tiles;
}

void BlockCache::evictToBudget() {
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

}  // namespace globe::io
