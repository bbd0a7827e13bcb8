// RGBA8 images on disk: any format stb_image reads (JPEG, PNG, ...) in, PNG out (atomically).
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "geo/result.hpp"

namespace globe::io {

// 8-bit RGBA, rows top-down (row 0 is the top of the picture), 4 bytes per pixel, no padding.
struct ImageRgba {
  int widthPixels = 0;
  int heightPixels = 0;
  std::vector<uint8_t> pixels;
};

// Decodes a JPEG/PNG/BMP/TGA/... file to RGBA8 (grey and RGB get alpha 255). Errors name the
// file and say what is wrong (missing, too large, undecodable and why).
Result<ImageRgba> loadImageRgba(const std::filesystem::path& path);

// Writes a PNG through writeFileAtomically: a failed write leaves no file (and no half file).
// rgba holds width·height·4 bytes, rows top-down.
Result<void> writePngAtomically(const std::filesystem::path& path, std::span<const uint8_t> rgba,
                                int widthPixels, int heightPixels);

}  // namespace globe::io
