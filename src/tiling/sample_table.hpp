// Heights of one pack's tiles read elsewhere (by the shards, for the merge), by slot and
// position index (tiling/sample_positions.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "tiling/sample_positions.hpp"

namespace globe::tiling {

class SampleTable {
 public:
  SampleTable(uint32_t tilesPerPack, uint32_t verticesPerSide)
      : perTile_(positionsPerTile(verticesPerSide)),
        values_(size_t{tilesPerPack} * perTile_, 0),
        present_(values_.size(), 0) {}

  bool set(size_t slot, uint32_t index, int16_t value) {
    const size_t at = slot * perTile_ + index;
    if (index >= perTile_ || at >= values_.size()) return false;
    values_[at] = value;
    present_[at] = 1;
    return true;
  }
  std::optional<int16_t> find(size_t slot, uint32_t index) const {
    const size_t at = slot * perTile_ + index;
    if (at >= values_.size() || present_[at] == 0) return std::nullopt;
    return values_[at];
  }

 private:
  uint32_t perTile_;
  std::vector<int16_t> values_;
  std::vector<uint8_t> present_;
};

// For the merge: the table, and which positions it must hold (those inside some shard's units);
// the rest the merge reads from its own sources.
struct PrecomputedSamples {
  const SampleTable* table = nullptr;
  std::function<bool(const SamplePosition&)> mustHold;
};

}  // namespace globe::tiling
