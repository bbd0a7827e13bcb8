// Pixel work on 256×256 RGBA imagery tiles: coverage tests, compositing, 2×2 averaging with
// premultiplied alpha, and the JPEG-or-PNG encoding choice.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "core/result.hpp"
#include "formats/image_io.hpp"

namespace globe::imagery_tiling {

inline constexpr int kImageryTileSizePixels = 256;

formats::ImageRgba transparentTile();
bool anyCovered(const formats::ImageRgba& tile);   // some pixel has alpha > 0
bool fullyOpaque(const formats::ImageRgba& tile);  // every pixel has alpha 255

// top = top over under (straight alpha in and out).
void compositeOver(formats::ImageRgba& top, const formats::ImageRgba& under);

// The parent tile from its children (NW, NE, SW, SE; nullopt = absent, transparent): each parent
// pixel averages 2×2 child pixels weighted by their alpha, so no-data never darkens an edge.
formats::ImageRgba averageChildren(
    const std::array<std::optional<formats::ImageRgba>, 4>& children);

// The same for tiles whose pixels are samples at the edges (formats::ImageryPixelGrid::Edges):
// the children's samples make one (2S−1)² grid, their shared edges being the same samples, and
// the parent's sample (r, c) lies on its (2r, 2c): a [1 2 1] filter each way around it, weighted
// by alpha; on the grid's border only along the border, so that neighbouring parents, which share
// those samples, compute the same edge. Integer arithmetic: the same bytes everywhere.
formats::ImageRgba downsampleEdgeSampledChildren(
    const std::array<std::optional<formats::ImageRgba>, 4>& children);

// JPEG when every pixel is opaque, PNG (RGBA) otherwise.
Result<std::vector<std::byte>> encodeTile(const formats::ImageRgba& tile, int jpegQuality,
                                          bool exactEdges = false);

}  // namespace globe::imagery_tiling
