// The pyramid's pack file: one file holds up to P×P neighbouring tiles of one level (big-endian).
//
//   offset 0   "GLOBEPK1", u32 version, u32 level, u32 packX, u32 packY, u32 P, u32 N,
//              u32 present tile count, u32 reserved                         (40 bytes)
//   offset 40  index: P×P entries in slot order (slot = localY·P + localX), 16 bytes each:
//              u64 block offset (0 = tile absent), i16 vertex min, i16 vertex max,
//              i16 subtree min, i16 subtree max     (metres: min with sea floors, max with water
//                                                        at 0 m, terrain::surfaceHeightRange)
//   then       the present blocks, N×N int16 samples each (terrain/height_block.hpp: GTOPO30
//              heights, -9999 and -32767..-20001 water), rows from the north
//   last       u32 CRC-32 of everything before it
//
// A reader parses the header and index once per pack, then loads any block with one read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <vector>

#include "geo/result.hpp"
#include "geo/tile_id.hpp"
#include "terrain/height_block.hpp"

namespace globe::io {

// 2: samples below 0 m are land, water is -9999 or band-coded with its sea floor (version 1
// read every negative sample as sea: such packs are refused, the pyramid must be re-tiled).
inline constexpr uint32_t kPackFormatVersion = 2;
inline constexpr size_t kPackHeaderBytes = 40;
inline constexpr size_t kPackEntryBytes = 16;
// decodePack refuses a pack whose in-memory blocks (all P×P slots) would exceed this.
inline constexpr uint64_t kPackMaximumMemoryBytes = uint64_t{1} << 30;

struct PackId {
  uint32_t level = 0;
  uint32_t x = 0;
  uint32_t y = 0;
  auto operator<=>(const PackId&) const = default;
};

struct PackEntry {
  uint64_t blockOffset = 0;
  terrain::HeightRange vertexRange;   // of this tile's own vertices
  terrain::HeightRange subtreeRange;  // of this tile's vertices and all its descendants'
  bool present() const { return blockOffset != 0; }
};

struct PackLayout {
  uint32_t tilesPerSide = 64;
  uint32_t verticesPerSide = 17;

  size_t blockBytes() const { return size_t{verticesPerSide} * verticesPerSide * 2; }
  size_t slotCount() const { return size_t{tilesPerSide} * tilesPerSide; }
  size_t indexEndOffset() const { return kPackHeaderBytes + slotCount() * kPackEntryBytes; }
  uint64_t fileBytes(size_t presentTiles) const {
    return indexEndOffset() + uint64_t{presentTiles} * blockBytes() + 4;
  }
};

PackId packOf(const geo::TileId& tile, uint32_t tilesPerSide);
size_t slotOf(const geo::TileId& tile, uint32_t tilesPerSide);
geo::TileId tileOfSlot(const PackId& pack, size_t slot, uint32_t tilesPerSide);

// PYRAMID/L<level>/<x>_<y>.pack
std::filesystem::path packPath(const std::filesystem::path& pyramidDir, const PackId& pack);

// A whole pack in memory, as the tiler builds it and as tests read it back.
struct Pack {
  PackId id;
  PackLayout layout;
  std::vector<PackEntry> entries;  // slotCount() entries; blockOffset != 0 marks a present tile
  std::vector<int16_t> heights;    // slotCount() blocks of N×N, absent slots unused

  static Pack empty(const PackId& id, const PackLayout& layout);
  std::span<int16_t> block(size_t slot);
  std::span<const int16_t> block(size_t slot) const;
  size_t presentCount() const;
};

// Serialises the pack; block offsets are assigned here in slot order.
std::vector<std::byte> encodePack(const Pack& pack);

// Parses and validates a whole pack file (sizes, offsets, CRC); errors name `path`.
Result<Pack> decodePack(std::span<const std::byte> bytes, const std::filesystem::path& path);

struct PackIndex {
  PackId id;
  PackLayout layout;
  std::vector<PackEntry> entries;
};

// The format version in a pack's first kPackHeaderBytes bytes, or nullopt when they are not a
// pack header (too short, another magic).
std::optional<uint32_t> packFormatVersionOf(std::span<const std::byte> head);
// Refuses every version but kPackFormatVersion, naming `path`; an older one says the pack was
// made by an older globe-tiler and must be re-tiled.
Result<void> checkPackFormatVersion(uint32_t version, const std::filesystem::path& path);

// Parses and validates the header and index (the first layout.indexEndOffset() bytes) of a pack
// whose file is fileBytes long.
Result<PackIndex> decodePackIndex(std::span<const std::byte> headAndIndex, uint64_t fileBytes,
                                  const std::filesystem::path& path);

// Decodes one block's big-endian samples.
void decodeBlock(std::span<const std::byte> bytes, std::span<int16_t> heights);

}  // namespace globe::io
