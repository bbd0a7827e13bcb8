// The pyramid's pack file: one file holds up to P×P neighbouring tiles of one level (big-endian).
//
//   offset 0   "GLOBEPK1", u32 version, u32 level, u32 packX, u32 packY, u32 P, u32 N,
//              u32 present tile count, u32 index bytes (stored; version 5)   (40 bytes)
//   offset 40  index: P×P entries in slot order (slot = localY·P + localX), 24 bytes each,
//              zlib-compressed (version 5: most slots of a deep level's pack are empty, and a
//              viewer over HTTP reads the index before any block):
//              u64 block offset (0 = tile absent), i16 vertex min, i16 vertex max,
//              i16 subtree min, i16 subtree max     (metres: min with sea floors, max with water
//                                                        at 0 m, terrain::surfaceHeightRange),
//              f32 geometric error (metres: how far the tile's surface, drawn with the mesh's
//                  diagonal rule, lies from its children's vertices, above or below, and at
//                  least its children's errors: src/tiling/pack_builder.hpp),
//              u32 CRC-32 of the block's stored bytes (a block read alone, by one range request
//                  over HTTP, is checked on its own)
//              In version 5 the stored block offset is 1 + its offset from the end of the index
//              (0 = absent), as the index's compressed size is not known before it is written;
//              PackEntry::blockOffset is the offset in the file either way.
//   then       the present blocks, (N+4)×(N+4) int16 samples each: the N×N vertices with their
//              apron (terrain::HeightBlock::apron, 2 vertices wide) around them, rows from the
//              north (row -2)
//              (terrain/height_block.hpp: GTOPO30 heights, -9999 and -32767..-20001 water)
//   last       u32 CRC-32 of everything before it
//
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
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "geo/tile_id.hpp"
#include "terrain/height_block.hpp"

namespace globe::formats {

// 2: samples below 0 m are land, water is -9999 or band-coded with its sea floor (version 1
// read every negative sample as sea: such packs are refused, the pyramid must be re-tiled).
// 3: blocks carry their apron, entries their geometric error. 4: entries carry their block's
// CRC. 5: the index is compressed. The tiler writes 5; 4, 3 and 2 are read.
inline constexpr uint32_t kPackFormatVersion = 5;
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
  uint32_t blockCrc = 0;  // CRC-32 of the stored block (version 4; 0 before)
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
  size_t indexEndOffset() const {
    return kPackHeaderBytes + (hasCompressedIndex() ? indexBytes : slotCount() * entryBytes());
  }
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

// A whole pack in memory, as the tiler builds it and as tests read it back.
struct Pack {
  PackId id;
  PackLayout layout;
  std::vector<PackEntry> entries;  // slotCount() entries; blockOffset != 0 marks a present tile
  std::vector<int16_t> heights;    // slotCount() blocks of N×N, absent slots unused
  std::vector<int16_t> aprons;     // slotCount() aprons (terrain::apronSampleCount), or empty

  // With aprons when the layout has them.
  static Pack empty(const PackId& id, const PackLayout& layout);
  std::span<int16_t> block(size_t slot);
  std::span<const int16_t> block(size_t slot) const;
  std::span<int16_t> apron(size_t slot);  // empty without aprons
  std::span<const int16_t> apron(size_t slot) const;
  size_t presentCount() const;
};

// Serialises the pack in layout.formatVersion; block offsets are assigned here in slot order.
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

// Decodes one stored block (layout.blockBytes() big-endian bytes) into its N×N heights and, when
// the layout has aprons, its apron (apronSampleCount samples; pass an empty span otherwise).
void decodeBlock(std::span<const std::byte> bytes, const PackLayout& layout,
                 std::span<int16_t> heights, std::span<int16_t> apron);

// "PATH: problem": how a pack that cannot be read is reported.
inline Error packError(const std::filesystem::path& path, const std::string& problem) {
  return makeError(path.string() + ": " + problem);
}

}  // namespace globe::formats
