// How a version-6 pack stores one block: its samples (the version-5 block: (N+4)² big-endian
// int16, apron included, rows from the north) predicted from their west, north and north-west
// neighbours (the plane through them), the residuals zigzagged (small magnitudes, small
// numbers), split into a plane of high bytes and one of low bytes, raw-DEFLATE compressed, then
// the CRC-32 of those compressed bytes. Terrain blocks shrink to ~42 % of their samples.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::formats {

inline constexpr int kBlockDeflateLevel = 6;  // level 9 saves < 0.2 % and costs more

// side: samples per row and column (N+4 with the apron).
std::vector<std::byte> encodeCompressedBlock(std::span<const std::byte> samplesBigEndian,
                                             size_t side);
// Into samplesBigEndian (side² × 2 bytes); an error saying what is wrong (CRC, inflate) without
// naming a file: the caller prefixes it.
Result<void> decodeCompressedBlock(std::span<const std::byte> stored, size_t side,
                                   std::span<std::byte> samplesBigEndian);

}  // namespace globe::formats
