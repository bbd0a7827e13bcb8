// What stb_image takes on trust in a PNG, checked first: it sizes its buffer for the compressed
// data by each chunk's declared length before reading the chunk (a 368-byte file declaring a
// 922 MB IDAT made it allocate 922 MB: found by fuzzing), and inflates the image data without
// bounding it by the image's size (a zlib bomb). Both are refused here, in 64 KiB of scratch.
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "core/result.hpp"

namespace globe::formats {

bool isPng(std::span<const std::byte> bytes);

// A PNG whose chunks each fit in `bytes` and whose image data inflates to no more than its
// header's width, height, depth and colour type need (the filter bytes included). Errors name
// `name`. For other bytes: nothing to check (success).
Result<void> checkPngStructure(std::span<const std::byte> bytes, const std::string& name);

}  // namespace globe::formats
