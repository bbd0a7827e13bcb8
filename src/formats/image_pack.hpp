// An imagery layer's pack file: one file holds up to P×P neighbouring tiles of one level, each an
// encoded image (JPEG or PNG) of any length (big-endian).
//
//   offset 0   "GLOBEIM1", u32 version, u32 level, u32 packX, u32 packY, u32 P,
//              u32 present tile count, u32 reserved, u32 reserved                 (40 bytes)
//   offset 40  index: P×P entries in slot order (slot = localY·P + localX), 16 bytes each:
//              u64 payload offset (0 = tile absent), u32 payload length, u32 CRC-32 of the payload
//   then       the present payloads, back to back in slot order
//   last       u32 CRC-32 of the header and index
//
// A reader parses the header and index once per pack (checking their CRC), then loads any tile
// with one read and checks that tile's own CRC.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "core/result.hpp"
#include "formats/pack_format.hpp"

namespace globe::formats {

inline constexpr uint32_t kImagePackFormatVersion = 1;
inline constexpr size_t kImagePackHeaderBytes = 40;
inline constexpr size_t kImagePackEntryBytes = 16;
inline constexpr uint32_t kImagePackMaxTilesPerSide = 256;
// A 256×256 RGBA PNG is at most ~260 KiB; anything beyond this is corrupt or hostile.
inline constexpr uint32_t kImageTileMaximumBytes = uint32_t{4} << 20;

struct ImagePackEntry {
  uint64_t offset = 0;  // 0 = absent
  uint32_t lengthBytes = 0;
  uint32_t crc = 0;
  bool present() const { return offset != 0; }
};

struct ImagePackIndex {
  PackId id;
  uint32_t tilesPerSide = 0;
  std::vector<ImagePackEntry> entries;  // P×P, slot order

  size_t presentCount() const;
};

// Bytes of the header and index of a pack with P tiles per side.
inline uint64_t imagePackIndexEndOffset(uint32_t tilesPerSide) {
  return kImagePackHeaderBytes + uint64_t{tilesPerSide} * tilesPerSide * kImagePackEntryBytes;
}

// payloads: P×P in slot order, an empty payload = tile absent.
std::vector<std::byte> encodeImagePack(const PackId& id, uint32_t tilesPerSide,
                                       const std::vector<std::vector<std::byte>>& payloads);

// Parses and validates the header and index (the first imagePackIndexEndOffset(P) bytes, or more)
// of a pack file of fileBytes bytes whose last 4 bytes are trailerCrc. Errors name `path`.
Result<ImagePackIndex> decodeImagePackIndex(std::span<const std::byte> headAndIndex,
                                            uint32_t trailerCrc, uint64_t fileBytes,
                                            const std::filesystem::path& path);

// Checks one tile's payload against its index entry; errors name `path` and the slot.
Result<void> checkImageTile(std::span<const std::byte> payload, const ImagePackEntry& entry,
                            size_t slot, const std::filesystem::path& path);

// A whole pack in memory: the index and every payload (checked), as the tiler and tests read it.
struct ImagePack {
  ImagePackIndex index;
  std::vector<std::vector<std::byte>> payloads;  // P×P, empty = absent
};
Result<ImagePack> decodeImagePack(std::span<const std::byte> bytes,
                                  const std::filesystem::path& path);

}  // namespace globe::formats
