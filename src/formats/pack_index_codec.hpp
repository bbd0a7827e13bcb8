// A version-6 pack's index before zlib: which slots are present, then one column per field over
// the present tiles in storage order (blocks are stored in that order too):
//
//   presence bitmap   ceil(P²/8) bytes; slot s is bit s % 8 (least significant first) of byte s / 8
//   u32 stored bytes  of each block (its compressed samples and CRC: pack_block_codec.hpp)
//   i16 ×4            vertex min, vertex max, subtree min, subtree max, each column as the
//                     difference from the previous tile's value (the first from 0), modulo 2^16
//   f32               geometric error
//
// Storage order is the Morton (Z-order) index of the tile's place in the pack, so the four
// children of a tile, and any square of 2^k × 2^k aligned tiles, are adjacent in the file: a
// viewer reads what it refines into with few range requests. Columns of differences between
// neighbours are what zlib shrinks: ~3 bytes a tile for a full pack (13 as version 5's rows).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "formats/pack_format.hpp"

namespace globe::formats {

// x's bits in the even places, y's in the odd.
uint64_t mortonKey(uint32_t x, uint32_t y);
// The present slots of a P×P pack in storage order.
std::vector<size_t> storageOrder(std::span<const PackEntry> entries, uint32_t tilesPerSide);
inline size_t presenceBitmapBytes(uint32_t tilesPerSide) {
  return (size_t{tilesPerSide} * tilesPerSide + 7) / 8;
}
inline size_t indexColumnBytes(size_t presentTiles) { return presentTiles * (4 + 4 * 2 + 4); }

// entries: every slot (present ones with storedBytes set); order: storageOrder of them.
std::vector<std::byte> encodeIndexColumns(std::span<const PackEntry> entries,
                                          std::span<const size_t> order, uint32_t tilesPerSide);
// Fills entries (P² of them) from inflated columns: every field but the block offsets, which
// are set from the stored sizes as consecutive from firstBlockOffset in storage order. Refuses
// a bitmap whose count is not presentTiles, and stored sizes beyond maxStoredBytes.
Result<void> decodeIndexColumns(std::span<const std::byte> columns, uint32_t tilesPerSide,
                                size_t presentTiles, uint64_t firstBlockOffset,
                                uint32_t maxStoredBytes, std::vector<PackEntry>& entries);

}  // namespace globe::formats
