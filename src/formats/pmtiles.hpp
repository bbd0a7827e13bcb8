// PMTiles v3 (github.com/protomaps/PMTiles, spec/v3): a single-file tile archive read by range.
// The 127-byte header, the varint directories (root, then leaves), and Hilbert tile ids.
// Decoded and checked, never trusted: counts are bounded by the bytes present.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::formats {

inline constexpr size_t kPmtilesHeaderBytes = 127;

enum class PmtilesCompression : uint8_t { Unknown = 0, None = 1, Gzip = 2, Brotli = 3, Zstd = 4 };
enum class PmtilesTileType : uint8_t {
  Unknown = 0,
  Mvt = 1,
  Png = 2,
  Jpeg = 3,
  Webp = 4,
  Avif = 5
};

struct PmtilesHeader {
  uint64_t rootOffset = 0, rootLength = 0;
  uint64_t metadataOffset = 0, metadataLength = 0;
  uint64_t leavesOffset = 0, leavesLength = 0;
  uint64_t tileDataOffset = 0, tileDataLength = 0;
  uint64_t addressedTiles = 0, tileEntries = 0, tileContents = 0;
  bool clustered = false;
  PmtilesCompression internalCompression = PmtilesCompression::Unknown;
  PmtilesCompression tileCompression = PmtilesCompression::Unknown;
  PmtilesTileType tileType = PmtilesTileType::Unknown;
  uint8_t minZoom = 0, maxZoom = 0;
  double westDegrees = -180, southDegrees = -90, eastDegrees = 180, northDegrees = 90;
  uint8_t centerZoom = 0;
  double centerLongitudeDegrees = 0, centerLatitudeDegrees = 0;
};

struct PmtilesEntry {
  uint64_t tileId = 0;
  uint64_t offset = 0;
  uint32_t length = 0;
  uint32_t runLength = 0;  // 0: a leaf directory at leavesOffset + offset
};

// Errors name `name`: not PMTiles, version other than 3, sections beyond `fileBytes`.
Result<PmtilesHeader> decodePmtilesHeader(std::span<const std::byte> bytes, uint64_t fileBytes,
                                          const std::string& name);
// A directory already decompressed.
Result<std::vector<PmtilesEntry>> decodePmtilesDirectory(std::span<const std::byte> bytes,
                                                         const std::string& name);
// The Hilbert tile id of z/x/y (z <= 26).
uint64_t pmtilesTileId(uint32_t z, uint64_t x, uint64_t y);
// Encoding, for the archives globe-tiler writes (publish/pmtiles_writer.hpp): the 127-byte
// header, and a directory (entries in tile id order) before any compression.
std::vector<std::byte> encodePmtilesHeader(const PmtilesHeader& header);
std::vector<std::byte> encodePmtilesDirectory(std::span<const PmtilesEntry> entries);
// The entry that holds `tileId` (a tile run covering it, or the leaf directory to search),
// nullopt when the directory has none.
std::optional<PmtilesEntry> findPmtilesEntry(const std::vector<PmtilesEntry>& entries,
                                             uint64_t tileId);

}  // namespace globe::formats
