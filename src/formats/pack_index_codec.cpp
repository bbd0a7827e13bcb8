#include "formats/pack_index_codec.hpp"

#include <algorithm>
#include <bit>

#include "core/big_endian.hpp"

namespace globe::formats {

uint64_t mortonKey(uint32_t x, uint32_t y) {
  uint64_t key = 0;
  for (unsigned bit = 0; bit < 32; ++bit) {
    key |= (uint64_t{(x >> bit) & 1U} << (2 * bit)) | (uint64_t{(y >> bit) & 1U} << (2 * bit + 1));
  }
  return key;
}

std::vector<size_t> storageOrder(std::span<const PackEntry> entries, uint32_t tilesPerSide) {
  std::vector<std::pair<uint64_t, size_t>> keyed;
  for (size_t slot = 0; slot < entries.size(); ++slot) {
    if (!entries[slot].present()) continue;
    keyed.emplace_back(mortonKey(static_cast<uint32_t>(slot % tilesPerSide),
                                 static_cast<uint32_t>(slot / tilesPerSide)),
                       slot);
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<size_t> order;
  order.reserve(keyed.size());
  for (const auto& [key, slot] : keyed) order.push_back(slot);
  return order;
}

std::vector<std::byte> encodeIndexColumns(std::span<const PackEntry> entries,
                                          std::span<const size_t> order, uint32_t tilesPerSide) {
  const size_t bitmapBytes = presenceBitmapBytes(tilesPerSide);
  std::vector<std::byte> out(bitmapBytes + indexColumnBytes(order.size()));
  for (size_t slot : order) out[slot / 8] |= static_cast<std::byte>(1U << (slot % 8));
  const size_t k = order.size();
  std::byte* sizes = &out[bitmapBytes];
  std::byte* heights = sizes + 4 * k;
  std::byte* errors = heights + 8 * k;
  int16_t previous[4] = {0, 0, 0, 0};
  for (size_t i = 0; i < k; ++i) {
    const PackEntry& e = entries[order[i]];
    core::storeBigEndian32(sizes + 4 * i, e.storedBytes);
    const int16_t values[4] = {e.vertexRange.minimumMeters, e.vertexRange.maximumMeters,
                               e.subtreeRange.minimumMeters, e.subtreeRange.maximumMeters};
    for (size_t c = 0; c < 4; ++c) {
      core::storeBigEndian16(heights + 2 * (c * k + i),
                             static_cast<uint16_t>(static_cast<uint16_t>(values[c]) -
                                                   static_cast<uint16_t>(previous[c])));
      previous[c] = values[c];
    }
    core::storeBigEndian32(errors + 4 * i, std::bit_cast<uint32_t>(e.geometricErrorMeters));
  }
  return out;
}

Result<void> decodeIndexColumns(std::span<const std::byte> columns, uint32_t tilesPerSide,
                                size_t presentTiles, uint64_t firstBlockOffset,
                                uint32_t maxStoredBytes, std::vector<PackEntry>& entries) {
  const size_t slots = size_t{tilesPerSide} * tilesPerSide;
  const size_t bitmapBytes = presenceBitmapBytes(tilesPerSide);
  if (columns.size() != bitmapBytes + indexColumnBytes(presentTiles)) {
    return makeError("pack index has the wrong size for its tile count");
  }
  std::vector<PackEntry> decoded(slots);
  size_t counted = 0;
  for (size_t slot = 0; slot < slots; ++slot) {
    if ((std::to_integer<unsigned>(columns[slot / 8]) >> (slot % 8)) & 1U) {
      decoded[slot].blockOffset = 1;  // present; the real offset below
      ++counted;
    }
  }
  if (counted != presentTiles) return makeError("pack index disagrees with its tile count");
  const std::vector<size_t> order = storageOrder(decoded, tilesPerSide);
  const size_t k = presentTiles;
  const std::byte* sizes = &columns[bitmapBytes];
  const std::byte* heights = sizes + 4 * k;
  const std::byte* errors = heights + 8 * k;
  uint64_t offset = firstBlockOffset;
  uint16_t running[4] = {0, 0, 0, 0};
  for (size_t i = 0; i < k; ++i) {
    PackEntry& e = decoded[order[i]];
    e.storedBytes = core::loadBigEndian32(sizes + 4 * i);
    if (e.storedBytes < 4 || e.storedBytes > maxStoredBytes) {
      return makeError("pack index entry " + std::to_string(order[i]) +
                       " has an impossible block size (" + std::to_string(e.storedBytes) +
                       " bytes)");
    }
    e.blockOffset = offset;
    offset += e.storedBytes;
    for (size_t c = 0; c < 4; ++c) {
      running[c] =
          static_cast<uint16_t>(running[c] + core::loadBigEndian16(heights + 2 * (c * k + i)));
    }
    e.vertexRange = {static_cast<int16_t>(running[0]), static_cast<int16_t>(running[1])};
    e.subtreeRange = {static_cast<int16_t>(running[2]), static_cast<int16_t>(running[3])};
    e.geometricErrorMeters = std::bit_cast<float>(core::loadBigEndian32(errors + 4 * i));
  }
  entries = std::move(decoded);
  return {};
}

}  // namespace globe::formats
