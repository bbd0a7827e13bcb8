// The pyramid's pack file: one file holds up to P×P neighbouring tiles of one level (big-endian).
//
//   offset 0   "GLOBEPK1", u32 version, u32 level, u32 packX, u32 packY, u32 P, u32 N,
//              u32 present tile count, u32 index bytes (stored; versions 5 and 6)   (40 bytes)
//   offset 40  version 6: the index, zlib-compressed: a presence bitmap, then columns over the
//              present tiles in storage order (Morton order of their place in the pack): each
//              block's stored bytes, the tile's vertex min/max and subtree min/max (metres: min
//              with sea floors, max with water at 0 m, terrain::surfaceHeightRange) as
//              differences from the previous tile's, and its f32 geometric error (metres: how far
//              the tile's surface, drawn with the mesh's diagonal rule, lies from its children's
//              vertices, above or below, and at least its children's errors:
//              src/tiling/pack_builder.hpp). Layout: formats/pack_index_codec.hpp.
//   then       the present blocks in storage order, each its (N+4)×(N+4) int16 samples (the N×N
//              vertices with their apron, terrain::HeightBlock::apron, 2 vertices wide, rows from
//              the north; terrain/height_block.hpp: GTOPO30 heights, -9999 and -32767..-20001
//              water) predicted, DEFLATE-compressed and followed by the CRC-32 of what is stored,
//              so a block read alone, by one range request over HTTP, is checked on its own
//              (formats/pack_block_codec.hpp)
//   last       u32 CRC-32 of everything before it
//
// Version 5 (still read): the index is P×P 24-byte entries in slot order (slot = localY·P +
// localX), zlib-compressed: u64 1 + the block's offset from the index's end (0 = absent), i16
// vertex min, max, subtree min, max, f32 geometric error, u32 CRC-32 of the block; blocks are
// the raw samples in slot order.
// Version 4 (still read): the index uncompressed, block offsets from the file's start.
// Version 3 (still read): 20-byte entries without the block CRC.
// Version 2 (still read): 16-byte entries without the geometric error, N×N blocks, no apron.
//
// A reader parses the header and index once per pack, then loads any block with one read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/result.hpp"
#include "geo/tile_id.hpp"
#include "terrain/height_block.hpp"

namespace globe::formats {

// 2: samples below 0 m are land, water is -9999 or band-coded with its sea floor (version 1
// read every negative sample as sea: such packs are refused, the pyramid must be re-tiled).
// 3: blocks carry their apron, entries their geometric error. 4: entries carry their block's
// CRC. 5: the index is compressed. 6: the index is columns, the blocks compressed and stored in
// Morton order. The tiler writes 6; 5, 4, 3 and 2 are read.
inline constexpr uint32_t kPackFormatVersion = 6;
// How much of a version-5 pack a reader asks for first: its header and (mostly) whole index.
inline constexpr size_t kPackFirstReadBytes = 16384;
inline constexpr uint32_t kOldestReadPackFormatVersion = 2;
inline constexpr size_t kPackHeaderBytes = 40;
constexpr size_t packEntryBytes(uint32_t formatVersion) {
  return formatVersion >= 4 ? 24 : formatVersion >= 3 ? 20 : 16;
}
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
  // Metres; NaN when the pack (version 2) does not say.
  float geometricErrorMeters = std::numeric_limits<float>::quiet_NaN();
  uint32_t blockCrc = 0;  // CRC-32 of the stored block (versions 4 and 5; 0 otherwise)
  // The block's bytes in the file: PackLayout::blockBytes() before version 6, its compressed
  // size and CRC in version 6 (set by decodePackIndex and encodePack; the tiler leaves it 0).
  uint32_t storedBytes = 0;
  bool present() const { return blockOffset != 0; }
};

struct PackLayout {
  uint32_t tilesPerSide = 64;
  uint32_t verticesPerSide = 17;
  uint32_t formatVersion = kPackFormatVersion;
  // Version 5: the compressed index's stored bytes, from the pack's header (0 until read).
  uint32_t indexBytes = 0;

  bool hasApron() const { return formatVersion >= 3; }
  bool hasBlockCrc() const { return formatVersion >= 4; }
  // Samples per stored block: N², or (N+2w)² with the apron (w = terrain::kApronWidth).
  size_t blockSamples() const {
    const size_t side = size_t{verticesPerSide} + (hasApron() ? 2 * terrain::kApronWidth : 0);
    return side * side;
  }
  size_t blockBytes() const { return blockSamples() * 2; }
  size_t entryBytes() const { return packEntryBytes(formatVersion); }
  size_t slotCount() const { return size_t{tilesPerSide} * tilesPerSide; }
  bool hasCompressedIndex() const { return formatVersion >= 5; }
  bool hasCompressedBlocks() const { return formatVersion >= 6; }
  // The most a version-6 block may take: DEFLATE's stored fallback of its samples and the CRC.
  uint32_t maxStoredBlockBytes() const {
    return static_cast<uint32_t>(blockBytes() + blockBytes() / 16 + 64);
  }
  size_t indexEndOffset() const {
    return kPackHeaderBytes + (hasCompressedIndex() ? indexBytes : slotCount() * entryBytes());
  }
  // Versions 2 to 5, whose blocks all take blockBytes().
  uint64_t fileBytes(size_t presentTiles) const {
    return indexEndOffset() + uint64_t{presentTiles} * blockBytes() + 4;
  }
};

PackId packOf(const geo::TileId& tile, uint32_t tilesPerSide);
size_t slotOf(const geo::TileId& tile, uint32_t tilesPerSide);
geo::TileId tileOfSlot(const PackId& pack, size_t slot, uint32_t tilesPerSide);

// "L<level>/<x>_<y>.pack": a pack's name inside its pyramid or layer (a file or a URL's tail).
std::string packName(const PackId& pack);
// PYRAMID/L<level>/<x>_<y>.pack
std::filesystem::path packPath(const std::filesystem::path& pyramidDir, const PackId& pack);

// Leaves new elements uninitialised (Pack::unset): a pack holds room for every slot's block, and
// filling the absent ones (most, in the coarse packs of regional data) was 40 % of the shards'
// merge. Only present slots are ever read.
template <typename T>
struct UninitialisedAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = UninitialisedAllocator<U>;
  };
  UninitialisedAllocator() = default;
  template <typename U>
  explicit UninitialisedAllocator(const UninitialisedAllocator<U>& /*other*/) noexcept {}
  template <typename U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
using PackSamples = std::vector<int16_t, UninitialisedAllocator<int16_t>>;

// A whole pack in memory, as the tiler builds it and as tests read it back.
struct Pack {
  PackId id;
  PackLayout layout;
  std::vector<PackEntry> entries;  // slotCount() entries; blockOffset != 0 marks a present tile
  PackSamples heights;             // slotCount() blocks of N×N, absent slots unset
  PackSamples aprons;              // slotCount() aprons (terrain::apronSampleCount), or empty

  // With aprons when the layout has them, every sample no data.
  static Pack empty(const PackId& id, const PackLayout& layout);
  // The same with the samples unset, for a writer that sets every sample of each slot it marks
  // present (the tiler, the decoder).
  static Pack unset(const PackId& id, const PackLayout& layout);
  std::span<int16_t> block(size_t slot);
  std::span<const int16_t> block(size_t slot) const;
  std::span<int16_t> apron(size_t slot);  // empty without aprons
  std::span<const int16_t> apron(size_t slot) const;
  size_t presentCount() const;
};

// Serialises the pack in layout.formatVersion; block offsets are assigned here (in slot order
// before version 6, in storage order from it).
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
// Refuses every version outside kOldestReadPackFormatVersion..kPackFormatVersion, naming `path`;
// an older one says the pack was made by an older globe-tiler and must be re-tiled.
Result<void> checkPackFormatVersion(uint32_t version, const std::filesystem::path& path);

// Parses and validates the header and index (the first layout.indexEndOffset() bytes) of a pack
// whose file is fileBytes long. A version-5 head shorter than its index is refused as truncated:
// packIndexEndOffset says how much to read.
Result<PackIndex> decodePackIndex(std::span<const std::byte> headAndIndex, uint64_t fileBytes,
                                  const std::filesystem::path& path);

// Where a pack's index ends, from its first kPackHeaderBytes bytes; nullopt when they are not a
// readable pack header.
std::optional<uint64_t> packIndexEndOffset(std::span<const std::byte> head);

// Decodes one block as the pack stores it (entry.storedBytes bytes at entry.blockOffset) into its
// N×N heights and, when the layout has aprons, its apron (apronSampleCount samples; pass an
// empty span otherwise), checking its CRC (versions 4 to 6). The error says what is wrong
// ("fails its CRC (corrupt pack)") for the caller to prefix with the file and tile.
Result<void> decodeStoredBlock(std::span<const std::byte> stored, const PackLayout& layout,
                               const PackEntry& entry, std::span<int16_t> heights,
                               std::span<int16_t> apron);

// Decodes one block's raw samples (layout.blockBytes() big-endian bytes, as versions 2 to 5
// store them).
void decodeBlock(std::span<const std::byte> bytes, const PackLayout& layout,
                 std::span<int16_t> heights, std::span<int16_t> apron);

// "PATH: problem": how a pack that cannot be read is reported.
inline Error packError(const std::filesystem::path& path, const std::string& problem) {
  return makeError(path.string() + ": " + problem);
}

}  // namespace globe::formats
