// Counters of one TerrainRenderer::draw call.
#pragma once

#include <cstdint>

namespace globe::render {

struct FrameStats {
  uint32_t tilesRequested = 0;  // entries in the tile list
  uint32_t tilesDrawn = 0;      // entries drawn (resident)
  uint32_t tilesMissing = 0;    // entries skipped because they were not uploaded
  uint32_t drawCalls = 0;
  uint64_t triangles = 0;  // submitted, skirts included, before culling
  // Tile vertex buffers + shared index buffer + global imagery texture + imagery tile textures.
  uint64_t gpuBytesResident = 0;
  uint32_t tilesResident = 0;
  uint32_t imageryTilesResident = 0;  // imagery tile textures, all layers
  uint64_t imageryBytesResident = 0;  // of those, mip chains included (part of gpuBytesResident)
  uint32_t drapesDrawn = 0;           // drape layers drawn, summed over the drawn tiles
  uint32_t drapesMissing = 0;         // drape layers skipped: their texture was not uploaded
  // Of drapesDrawn, those magnified over the whole tile, drawn with the bilinear sampler.
  uint32_t drapesMagnified = 0;
};

}  // namespace globe::render
