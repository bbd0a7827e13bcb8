// Counters of one TerrainRenderer::draw call.
#pragma once

#include <cstdint>

namespace globe::render {

struct FrameStats {
  uint32_t tilesRequested = 0;  // entries in the tile list
  uint32_t tilesDrawn = 0;      // entries drawn (resident)
  uint32_t tilesMissing = 0;    // entries skipped because they were not uploaded
  uint32_t drawCalls = 0;
  uint64_t triangles = 0;         // submitted, skirts included, before culling
  uint64_t gpuBytesResident = 0;  // tile vertex buffers + shared index buffer + imagery texture
  uint32_t tilesResident = 0;
};

}  // namespace globe::render
