// Walks the chunks (length, type, data, CRC), then inflates the IDAT data chunk by chunk through
// a small buffer, counting: more than the header implies is a bomb, refused before stb sees it.
#include "formats/png_check.hpp"

#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "core/big_endian.hpp"

namespace globe::formats {
namespace {

constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};

// Bytes of filtered image data the header implies (interlaced: the seven passes' rows are
// shorter, bounded by the whole image's rows plus a filter byte a row a pass).
uint64_t expectedRawBytes(uint32_t width, uint32_t height, int depth, int colourType,
                          bool interlaced) {
  static constexpr int kChannels[7] = {1, 0, 3, 1, 2, 0, 4};  // by colour type 0..6
  const int channels = colourType >= 0 && colourType < 7 ? kChannels[colourType] : 0;
  const uint64_t rowBytes = (uint64_t{width} * static_cast<uint64_t>(channels * depth) + 7) / 8;
  return (rowBytes + 1) * height + (interlaced ? uint64_t{7} * (height + 1) * 2 : 0);
}

// How many bytes the IDAT parts inflate to, counting no further than `limit` + 1.
uint64_t inflatedBytes(const std::vector<std::span<const std::byte>>& parts, uint64_t limit) {
  z_stream z{};
  if (inflateInit(&z) != Z_OK) return 0;
  unsigned char scratch[1 << 16];
  uint64_t total = 0;
  int status = Z_OK;
  for (const auto& part : parts) {
    z.next_in = reinterpret_cast<Bytef*>(const_cast<std::byte*>(part.data()));
    z.avail_in = static_cast<uInt>(part.size());
    while (status == Z_OK && total <= limit && (z.avail_in > 0 || z.avail_out == 0)) {
      z.next_out = scratch;
      z.avail_out = sizeof scratch;
      status = inflate(&z, Z_NO_FLUSH);
      total += sizeof scratch - z.avail_out;
      if (status == Z_BUF_ERROR && z.avail_in == 0) status = Z_OK;  // wants the next part
    }
    if (status != Z_OK || total > limit) break;
  }
  inflateEnd(&z);
  return total;
}

}  // namespace

bool isPng(std::span<const std::byte> bytes) {
  return bytes.size() >= 8 && std::memcmp(bytes.data(), kSignature, 8) == 0;
}

Result<void> checkPngStructure(std::span<const std::byte> bytes, const std::string& name) {
  if (!isPng(bytes)) return {};
  std::vector<std::span<const std::byte>> imageData;
  uint64_t expected = 0;
  for (size_t at = 8; at < bytes.size();) {
    if (bytes.size() - at < 12) return makeError(name + ": PNG cut short in a chunk header");
    const uint32_t length = core::loadBigEndian32(bytes.data() + at);
    const std::byte* type = bytes.data() + at + 4;
    if (length > bytes.size() - at - 12) {
      return makeError(name + ": PNG chunk declares " + std::to_string(length) + " bytes, " +
                       std::to_string(bytes.size() - at - 12) + " are left");
    }
    const std::byte* data = type + 4;
    if (std::memcmp(type, "IHDR", 4) == 0 && length >= 13) {
      expected = expectedRawBytes(core::loadBigEndian32(data), core::loadBigEndian32(data + 4),
                                  std::to_integer<int>(data[8]), std::to_integer<int>(data[9]),
                                  std::to_integer<int>(data[12]) != 0);
    } else if (std::memcmp(type, "IDAT", 4) == 0) {
      imageData.emplace_back(data, length);
    } else if (std::memcmp(type, "IEND", 4) == 0) {
      break;
    }
    at += size_t{length} + 12;
  }
  if (imageData.empty() || expected == 0) return {};  // stb's to refuse
  if (inflatedBytes(imageData, expected) > expected) {
    return makeError(name + ": PNG image data inflates to more than the " +
                     std::to_string(expected) + " bytes its header gives");
  }
  return {};  // a broken stream is stb's to report
}

}  // namespace globe::formats
