// Fast tile encoders for the imagery tiler: JPEG through libjpeg-turbo (with GDAL's Debian packages)
// and PNG through formats/png_encoder (libdeflate). stb's encoders spent most of a tiling run
// compressing; these give the same pictures several times faster.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/result.hpp"
#include "formats/image_io.hpp"

namespace globe::imagery_tiling {

// Baseline JPEG, 4:2:0, integer DCT (the same bytes on every machine); alpha ignored. With
// exactEdges, the border ring's exact samples ride along in an APP9 segment
// (formats/tile_edges.hpp).
Result<std::vector<std::byte>> encodeJpegFast(const formats::ImageRgba& image, int quality,
                                              bool exactEdges = false);
// 8-bit RGBA PNG, each row's filter chosen by the minimum-sum-of-differences heuristic.
Result<std::vector<std::byte>> encodePngFast(const formats::ImageRgba& image);
// 8-bit grey+alpha PNG of width × height pixel pairs (grey, alpha), row by row.
Result<std::vector<std::byte>> encodePngGreyAlphaFast(std::span<const uint8_t> greyAlpha,
                                                      int widthPixels, int heightPixels);

}  // namespace globe::imagery_tiling
