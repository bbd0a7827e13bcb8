// globe-tiler water-mask: land polygons (GSHHG, Natural Earth, OpenStreetMap's land polygons, any
// vector file OGR opens) to a water-mask layer on the terrain's quadtree: 256×256 edge-sampled
// tiles of the water fraction around each sample (antialiased), in the image packs and layer.json
// of imagery layers (formats::LayerKind::WaterMask). The viewer takes it as the sea flag per
// fragment where the terrain's own sources are coarser, so a coarse grid's coasts are drawn where
// the shoreline is.
//
// The tree is built from the top: each tile's rings are its parent's clipped to it, and it is
// split only where a shoreline (or where one layer's extent gives way to another) runs through
// it, down to the finest level of the layers there. Where several layers cover a sample, the one
// with the finest shoreline decides, blended into the next coarser one near the sides of its
// extent (no straight cut where a regional file ends); outside every layer's extent samples are
// transparent (alpha 0: the terrain decides).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "tiling/progress.hpp"

namespace globe::mask_tiling {

inline constexpr int kWaterMaskSupersample = 4;  // per side, per sample: 16 points per texel
inline constexpr uint32_t kWaterMaskMaxAutoLevel = 13;

struct WaterMaskTilerOptions {
  std::vector<std::string> inputs;  // vector files of land polygons
  std::filesystem::path outputDir;
  // Deepest level; default per layer: the first whose texel is at most half the layer's median
  // shoreline edge (finer tiles would only draw its straight edges), at most
  // kWaterMaskMaxAutoLevel.
  std::optional<uint32_t> maxLevel;
  uint32_t packTilesPerSide = 16;
  unsigned threads = 0;  // 0 = every core
  tiling::ProgressSink progress;
};

struct WaterMaskTilerReport {
  uint64_t tiles = 0;
  uint64_t coastTiles = 0;  // tiles a shoreline crosses (the rest are all water or all land)
  uint32_t maxLevel = 0;
  uint64_t layers = 0, rings = 0, vertices = 0;
  double seconds = 0;
};

Result<WaterMaskTilerReport> runWaterMaskTiler(const WaterMaskTilerOptions& options);

// The deepest level worth tiling for shorelines whose median edge is this long (degrees).
uint32_t waterMaskLevelFor(double medianEdgeDegrees);

}  // namespace globe::mask_tiling
