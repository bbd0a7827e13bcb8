// Big-endian encoding helpers: GTOPO30 samples and the pyramid's pack files are big-endian on disk.
#pragma once

#include <cstddef>
#include <cstdint>

namespace globe::core {

inline void storeBigEndian16(std::byte* out, uint16_t value) {
  out[0] = std::byte(value >> 8);
  out[1] = std::byte(value & 0xFF);
}
inline void storeBigEndian32(std::byte* out, uint32_t value) {
  for (int i = 0; i < 4; ++i) out[i] = std::byte((value >> (24 - 8 * i)) & 0xFF);
}
inline void storeBigEndian64(std::byte* out, uint64_t value) {
  for (int i = 0; i < 8; ++i) out[i] = std::byte((value >> (56 - 8 * i)) & 0xFF);
}
inline uint16_t loadBigEndian16(const std::byte* in) {
  return static_cast<uint16_t>((std::to_integer<uint16_t>(in[0]) << 8) |
                               std::to_integer<uint16_t>(in[1]));
}
inline uint32_t loadBigEndian32(const std::byte* in) {
  uint32_t value = 0;
  for (int i = 0; i < 4; ++i) value = (value << 8) | std::to_integer<uint32_t>(in[i]);
  return value;
}
inline uint64_t loadBigEndian64(const std::byte* in) {
  uint64_t value = 0;
  for (int i = 0; i < 8; ++i) value = (value << 8) | std::to_integer<uint64_t>(in[i]);
  return value;
}

}  // namespace globe::core
