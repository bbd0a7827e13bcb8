// zlib and raw DEFLATE through libdeflate, for what the packs compress (indexes, blocks): one
// compressor and decompressor per thread, whole buffers at once.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace globe::compression {

// level 1 (fast) .. 12 (smallest).
std::vector<std::byte> zlibCompress(std::span<const std::byte> in, int level);
std::vector<std::byte> deflateCompress(std::span<const std::byte> in, int level);
std::vector<std::byte> gzipCompress(std::span<const std::byte> in, int level);
// True when `in` inflates to exactly out.size() bytes (no more, no fewer).
bool zlibInflateExactly(std::span<const std::byte> in, std::span<std::byte> out);
bool deflateInflateExactly(std::span<const std::byte> in, std::span<std::byte> out);

}  // namespace globe::compression
