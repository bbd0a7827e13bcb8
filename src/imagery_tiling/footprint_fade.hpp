// Where a layer's footprint ends, its alpha fades over a few source pixels instead of cutting,
// so a scene blends into the layer under it (the Blue Marble under a Landsat scene) rather than
// lying on it like a tablecloth. Only at the layer's outer edges: not where a neighbouring input
// of like resolution continues it (a mosaic of scenes), not at ±180° or a pole of a raster that
// reaches them. Towards a raster's own no-data (an irregular collar around a scene) alpha fades
// likewise, from the nearest transparent source pixel.
#pragma once

#include <cstdint>
#include <vector>

#include "imagery_tiling/imagery_input.hpp"

namespace globe::imagery_tiling {

// Sets fadeEdges and fadeCollars of every raster input of an edge-sampled layer (none for
// pixel-is-area layers, whose bytes stay as they were).
void chooseFootprintFades(std::vector<ImageryInput>& inputs);

// The factor on alpha at source pixel coordinates (x, y) of a columns × rows raster:
// smoothstep(0, kFootprintFadePixels, distance to the nearest fading edge), 1 without one.
double footprintFade(const ImageryInput& input, double x, double y, int columns, int rows);

// smoothstep(0, kFootprintFadePixels, distance): the factor on alpha that far from the edge.
double smoothFade(double distancePixels);

// distance[i]: how far (pixels, chamfer 3-4) pixel i of a width × height RGBA image is from the
// nearest one with alpha 0; very large where there is none.
void distanceToTransparent(const std::vector<uint8_t>& rgba, int width, int height,
                           std::vector<float>& distance);

}  // namespace globe::imagery_tiling
