// globe-tiler imagery: builds an imagery layer (256×256 JPEG/PNG tiles on the terrain's quadtree,
// in packs) from rasters and TMS trees: level by level from the finest, tiles in parallel, every
// file written atomically, resumable after a kill, the same bytes for any thread count.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "imagery_tiling/imagery_input.hpp"
#include "tiling/progress.hpp"

namespace globe::imagery_tiling {

struct ImageryTilerOptions {
  std::vector<std::string> inputs;
  std::filesystem::path outputDir;
  ImageryInputOptions input;  // --bounds, --bands, --scale, --max-level
  uint32_t packTilesPerSide = 16;
  int jpegQuality = 85;
  unsigned threads = 0;           // 0 = every core
  tiling::ProgressSink progress;  // how far the run is; empty: not reported
};

struct ImageryTilerReport {
  uint64_t tiles = 0;
  uint64_t tilesBuilt = 0;   // tiles rendered in this run (not in reused packs)
  uint64_t tilesCopied = 0;  // TMS tiles re-packed as they were
  uint64_t packsBuilt = 0;
  uint64_t packsReused = 0;  // complete packs found from an earlier, interrupted run
  uint32_t maxLevel = 0;
  double seconds = 0;
  std::vector<std::string> warnings;  // one line each, naming the input (a guessed band choice)
};

Result<ImageryTilerReport> runImageryTiler(const ImageryTilerOptions& options);

}  // namespace globe::imagery_tiling
