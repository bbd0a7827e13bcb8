// How much of the ground around each sample of a tile is land: the even-odd fill of polygon
// rings, counted on a supersample × supersample grid of points in the texel-sized box centred on
// each sample (a box filter: coastlines come out antialiased, a strait narrower than a texel as
// a partly-water texel rather than a gap or nothing).
#pragma once

#include <cstdint>
#include <vector>

#include "mask_tiling/ring_clip.hpp"

namespace globe::mask_tiling {

// size × size samples, sample (r, c) at longitude west + c·step, latitude north − r·step (the
// edge-sampled grid of imagery layers: formats::ImageryPixelGrid::Edges).
struct TexelGrid {
  double westDegrees = 0, northDegrees = 0, stepDegrees = 0;
  int size = 256;
};

// counts[r·size + c]: how many of the box's supersample² points are inside an odd number of
// rings, 0..supersample². The rings must cover the boxes (clip them to the grid's rectangle grown
// by one step).
void countLandPoints(const std::vector<Ring>& rings, const TexelGrid& grid, int supersample,
                     std::vector<uint16_t>& counts);

}  // namespace globe::mask_tiling
