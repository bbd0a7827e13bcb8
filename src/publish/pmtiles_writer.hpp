// Writes a PMTiles v3 archive (github.com/protomaps/PMTiles, spec/v3) tile by tile: tiles are
// given in tile id order and spooled to a temporary file, identical tiles stored once (a repeat
// right after its twin lengthens its entry's run); finish() lays out header, root directory,
// metadata, leaf directories and tile data in a second temporary and renames it into place, so
// the archive is whole or absent. The directories are gzip-compressed, the root kept within the
// first 16 KiB as readers expect.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/result.hpp"
#include "formats/pmtiles.hpp"

namespace globe::publish {

struct PmtilesSummary {
  uint64_t addressedTiles = 0;  // tiles the archive answers for
  uint64_t tileEntries = 0;     // directory entries (runs of one tile's bytes)
  uint64_t tileContents = 0;    // distinct tiles stored
  uint64_t leafDirectories = 0;
  uint64_t archiveBytes = 0;
};

class PmtilesWriter {
 public:
  // Errors name the temporaries it cannot create beside `archive`.
  static Result<std::unique_ptr<PmtilesWriter>> create(const std::filesystem::path& archive);
  ~PmtilesWriter();
  PmtilesWriter(const PmtilesWriter&) = delete;
  PmtilesWriter& operator=(const PmtilesWriter&) = delete;

  // Tiles in increasing pmtilesTileId order (zoom by zoom, Hilbert order within a zoom).
  Result<void> add(uint32_t zoom, uint32_t x, uint32_t y, std::span<const std::byte> bytes);
  // `header` gives the tile type, zooms, bounds and centre; its offsets, counts and compressions
  // are filled here. `metadataJson` is stored gzip-compressed.
  Result<PmtilesSummary> finish(formats::PmtilesHeader header, const std::string& metadataJson);

 private:
  PmtilesWriter(std::filesystem::path archive, std::filesystem::path spool, std::FILE* file);
  // Whether the spooled bytes at `offset` are `bytes`.
  Result<bool> spooledEquals(uint64_t offset, std::span<const std::byte> bytes);
  void removeTemporaries();

  std::filesystem::path archive_, spool_;
  std::FILE* spoolFile_ = nullptr;
  uint64_t spooledBytes_ = 0;
  std::vector<formats::PmtilesEntry> entries_;
  // Content hash → offsets of the distinct tiles with that hash.
  std::unordered_map<uint64_t, std::vector<uint64_t>> offsetsByHash_;
  uint64_t contents_ = 0;
};

}  // namespace globe::publish
