// PNG encoding through libdeflate: per row the best of the five filters, then one deflate
// stream (level 6, or the caller's). Several times faster than stb_image_write's, and as small or
// smaller.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/result.hpp"

namespace globe::formats {

// 8-bit RGBA, grey+alpha. An error for a size that does not match the pixels.
Result<std::vector<std::byte>> encodePngRgba(std::span<const uint8_t> rgba, int widthPixels,
                                             int heightPixels);
// How hard to try for small files.
struct PngEncoding {
  int deflateLevel = 6;         // libdeflate's, 1..12
  bool adaptiveFilters = true;  // per row the best of the five filters, else Up on every row
};

// 8-bit RGB (no alpha: an elevation tile's pixels are all opaque). An error for a deflate level
// outside 1..12.
Result<std::vector<std::byte>> encodePngRgb(std::span<const uint8_t> rgb, int widthPixels,
                                            int heightPixels, PngEncoding encoding = {});
Result<std::vector<std::byte>> encodePngGreyAlpha(std::span<const uint8_t> greyAlpha,
                                                  int widthPixels, int heightPixels);

}  // namespace globe::formats
