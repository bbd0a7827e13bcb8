// RGBA8 images: any format stb_image reads (JPEG, PNG, ...) in, from files or memory; PNG out
// (atomically), JPEG and PNG to memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::formats {

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

// Decodes an image held in memory (an imagery tile) to RGBA8; refuses images larger than
// kMaxDecodedImageSide on a side before decoding. Errors name `name`.
inline constexpr int kMaxDecodedImageSide = 4096;
Result<ImageRgba> decodeImageRgba(std::span<const std::byte> bytes, const std::string& name);

// Encodes to JPEG (alpha ignored; quality 1..100) or PNG (RGBA) in memory.
Result<std::vector<std::byte>> encodeJpeg(const ImageRgba& image, int quality);
Result<std::vector<std::byte>> encodePng(const ImageRgba& image);

}  // namespace globe::formats
