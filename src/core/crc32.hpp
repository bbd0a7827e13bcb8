// CRC-32 (IEEE 802.3), used to validate complete pack files when a tiling run resumes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace globe::core {

uint32_t crc32(std::span<const std::byte> bytes, uint32_t previous = 0);

}  // namespace globe::core
