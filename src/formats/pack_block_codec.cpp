#include "formats/pack_block_codec.hpp"

#include "core/big_endian.hpp"
#include "core/crc32.hpp"
#include "compression/deflate_bytes.hpp"

namespace globe::formats {
namespace {

// The plane through the west, north and north-west samples; along the first row the west one,
// down the first column the north one.
int predicted(const std::vector<int>& s, size_t side, size_t row, size_t column) {
  if (row == 0) return column == 0 ? 0 : s[column - 1];
  if (column == 0) return s[(row - 1) * side];
  return s[row * side + column - 1] + s[(row - 1) * side + column] -
         s[(row - 1) * side + column - 1];
}

uint16_t zigzag(int residual) {
  const auto r = static_cast<int16_t>(residual);  // modulo 2^16: any int16 input round-trips
  return static_cast<uint16_t>((static_cast<uint16_t>(r) << 1) ^ static_cast<uint16_t>(r >> 15));
}

int16_t unzigzag(uint16_t z) {
  return static_cast<int16_t>(static_cast<uint16_t>((z >> 1) ^ (0U - (z & 1U))));
}

}  // namespace

std::vector<std::byte> encodeCompressedBlock(std::span<const std::byte> samplesBigEndian,
                                             size_t side) {
  const size_t count = side * side;
  std::vector<int> samples(count);
  for (size_t i = 0; i < count; ++i) {
    samples[i] = static_cast<int16_t>(core::loadBigEndian16(&samplesBigEndian[2 * i]));
  }
  std::vector<std::byte> planes(2 * count);
  for (size_t row = 0; row < side; ++row) {
    for (size_t column = 0; column < side; ++column) {
      const size_t i = row * side + column;
      const uint16_t z = zigzag(samples[i] - predicted(samples, side, row, column));
      planes[i] = static_cast<std::byte>(z >> 8);
      planes[count + i] = static_cast<std::byte>(z & 0xFFU);
    }
  }
  std::vector<std::byte> stored = compression::deflateCompress(planes, kBlockDeflateLevel);
  const size_t body = stored.size();
  stored.resize(body + 4);
  core::storeBigEndian32(&stored[body], core::crc32(std::span(stored).first(body)));
  return stored;
}

Result<void> decodeCompressedBlock(std::span<const std::byte> stored, size_t side,
                                   std::span<std::byte> samplesBigEndian) {
  const size_t count = side * side;
  if (stored.size() < 4 || samplesBigEndian.size() != 2 * count) {
    return makeError("a block shorter than its CRC");
  }
  const std::span<const std::byte> body = stored.first(stored.size() - 4);
  if (core::crc32(body) != core::loadBigEndian32(&stored[body.size()])) {
    return makeError("fails its CRC");
  }
  std::vector<std::byte> planes(2 * count);
  if (!compression::deflateInflateExactly(body, planes)) {
    return makeError("does not inflate to its " + std::to_string(count) + " samples");
  }
  std::vector<int> samples(count);
  for (size_t row = 0; row < side; ++row) {
    for (size_t column = 0; column < side; ++column) {
      const size_t i = row * side + column;
      const auto z = static_cast<uint16_t>((std::to_integer<unsigned>(planes[i]) << 8) |
                                           std::to_integer<unsigned>(planes[count + i]));
      const auto value = static_cast<int16_t>(predicted(samples, side, row, column) + unzigzag(z));
      samples[i] = value;
      core::storeBigEndian16(&samplesBigEndian[2 * i], static_cast<uint16_t>(value));
    }
  }
  return {};
}

}  // namespace globe::formats
