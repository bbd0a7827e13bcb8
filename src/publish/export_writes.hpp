// How the exporters write a tree of tiles: each file atomically (a temporary name, then rename),
// one already there kept, so a run killed at any moment is resumed by running it again; and
// what they report.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::publish {

struct ExportReport {
  uint64_t tilesWritten = 0;
  uint64_t tilesKept = 0;  // already written by an earlier run
  uint64_t bytesWritten = 0;
};

// The region and levels to export; levels beyond the pyramid's are not exported.
struct ExportRegion {
  uint32_t minLevel = 0;
  uint32_t maxLevel = UINT32_MAX;
  double westDegrees = -180, southDegrees = -90, eastDegrees = 180, northDegrees = 90;
};

// Hears (tiles done, tiles in the run) as a run goes, from one thread at a time; the program
// prints it.
using ExportProgress = std::function<void(uint64_t tilesDone, uint64_t tilesTotal)>;

// How a run is carried out: on how many threads (the same bytes on any number), heard by whom.
struct ExportWork {
  unsigned threads = 1;
  ExportProgress progress;
};

// "A-B" or "A" into the region's levels (or zooms); false when the text is neither.
bool parseExportLevels(const std::string& text, ExportRegion& region);
// "W,S,E,N" in degrees (W < E, S < N, within the world) into the region; false otherwise.
bool parseExportBounds(const std::string& text, ExportRegion& region);

// Calls make() and writes its bytes to `path` unless a file is already there.
Result<void> writeTileOnce(const std::filesystem::path& path,
                           const std::function<Result<std::vector<std::byte>>()>& make,
                           ExportReport& report);

// Writes `bytes` to `path` (its folder made), replacing a file there, atomically (a tile's fixed
// child mask, layer.json).
Result<void> writeFileReplacing(const std::filesystem::path& path,
                                std::span<const std::byte> bytes);

}  // namespace globe::publish
