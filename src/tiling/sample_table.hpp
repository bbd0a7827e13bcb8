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
      : perTile_(positionsPerTile(verticesPerSide)), rowOfSlot_(tilesPerPack, kNone) {}

  bool set(size_t slot, uint32_t index, int16_t value) {
    if (slot >= rowOfSlot_.size() || index >= perTile_) return false;
    if (rowOfSlot_[slot] == kNone) {  // only the slots some shard wrote take memory
      rowOfSlot_[slot] = static_cast<uint32_t>(values_.size() / perTile_);
      values_.resize(values_.size() + perTile_, 0);
      present_.resize(present_.size() + perTile_, 0);
    }
    const size_t at = size_t{rowOfSlot_[slot]} * perTile_ + index;
    values_[at] = value;
    present_[at] = 1;
    return true;
  }
  std::optional<int16_t> find(size_t slot, uint32_t index) const {
    if (slot >= rowOfSlot_.size() || index >= perTile_ || rowOfSlot_[slot] == kNone) {
      return std::nullopt;
    }
    const size_t at = size_t{rowOfSlot_[slot]} * perTile_ + index;
    if (present_[at] == 0) return std::nullopt;
    return values_[at];
  }

 private:
  static constexpr uint32_t kNone = UINT32_MAX;
  uint32_t perTile_;
  std::vector<uint32_t> rowOfSlot_;
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
