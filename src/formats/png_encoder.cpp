#include "formats/png_encoder.hpp"

#include <libdeflate.h>

#include <array>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "core/big_endian.hpp"

namespace globe::formats {
namespace {

void appendChunk(std::vector<std::byte>& out, const char type[4], std::span<const std::byte> data) {
  const size_t start = out.size();
  out.resize(start + 12 + data.size());
  core::storeBigEndian32(&out[start], static_cast<uint32_t>(data.size()));
  std::memcpy(&out[start + 4], type, 4);
  if (!data.empty()) std::memcpy(&out[start + 8], data.data(), data.size());
  // libdeflate's CRC-32 (the same polynomial as core::crc32), several times faster on a tile.
  const uint32_t crc = libdeflate_crc32(0, &out[start + 4], 4 + data.size());
  core::storeBigEndian32(&out[start + 8 + data.size()], crc);
}

int paeth(int a, int b, int c) {
  const int p = a + b - c;
  const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  return pa <= pb && pa <= pc ? a : (pb <= pc ? b : c);
}

struct CompressorDeleter {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

// One compressor per thread and level: allocating one costs more than compressing a tile.
libdeflate_compressor* compressorOf(int level) {
  thread_local std::array<std::unique_ptr<libdeflate_compressor, CompressorDeleter>, 13>
      compressors;
  auto& compressor = compressors[static_cast<size_t>(level)];
  if (!compressor) compressor.reset(libdeflate_alloc_compressor(level));
  return compressor.get();
}

// The PNG filter (RFC 2083 6.1) each row of 8-bit pixels of `channels` bytes gets, followed by
// the filtered row: per row the best of the five (the least sum of absolute differences), or
// Up everywhere. `channels` a constant, so that the filter loops vectorise.
template <size_t channels>
std::vector<uint8_t> filterRows(const uint8_t* pixels, int widthPixels, int heightPixels,
                                bool adaptive) {
  const size_t stride = static_cast<size_t>(widthPixels) * channels;
  const auto rows = static_cast<size_t>(heightPixels);
  std::vector<uint8_t> filtered(rows * (stride + 1));
  std::vector<uint8_t> candidate[5];
  for (auto& c : candidate) c.resize(stride);
  const std::vector<uint8_t> zeros(stride, 0);
  for (size_t r = 0; r < rows; ++r) {
    const uint8_t* row = &pixels[r * stride];
    const uint8_t* above = r > 0 ? row - stride : zeros.data();
    // One tight loop per filter type (they vectorise); a and c are 0 for the first pixel.
    auto filter = [&](int type, auto predict) {
      uint8_t* out = candidate[type].data();
      uint32_t cost = 0;
      for (size_t i = 0; i < stride; ++i) {
        const int a = i >= channels ? row[i - channels] : 0, b = above[i],
                  c = i >= channels ? above[i - channels] : 0;
        out[i] = static_cast<uint8_t>(row[i] - predict(a, b, c));
        cost += static_cast<uint32_t>(std::abs(static_cast<int8_t>(out[i])));
      }
      return cost;
    };
    constexpr int kUp = 2;
    int best = kUp;
    if (adaptive) {
      const uint32_t costs[5] = {
          filter(0, [](int, int, int) { return 0; }),
          filter(1, [](int a, int, int) { return a; }),
          filter(kUp, [](int, int b, int) { return b; }),
          filter(3, [](int a, int b, int) { return (a + b) / 2; }),
          filter(4, [](int a, int b, int c) { return paeth(a, b, c); }),
      };
      best = 0;
      for (int type = 1; type < 5; ++type) {
        if (costs[type] < costs[best]) best = type;
      }
    } else {
      filter(kUp, [](int, int b, int) { return b; });
    }
    filtered[r * (stride + 1)] = static_cast<uint8_t>(best);
    std::memcpy(&filtered[r * (stride + 1) + 1], candidate[best].data(), stride);
  }
  return filtered;
}

// 8-bit PNG of `channels` 1 (grey), 2 (grey, alpha), 3 (RGB) or 4 (RGBA) bytes per pixel.
template <size_t channels>
Result<std::vector<std::byte>> encodePngChannels(const uint8_t* pixels, int widthPixels,
                                                 int heightPixels, PngEncoding encoding = {}) {
  const std::vector<uint8_t> filtered =
      filterRows<channels>(pixels, widthPixels, heightPixels, encoding.adaptiveFilters);
  libdeflate_compressor* compressor = compressorOf(encoding.deflateLevel);
  if (!compressor) return makeError("PNG encoding failed: cannot allocate a compressor");
  std::vector<std::byte> zlib(libdeflate_zlib_compress_bound(compressor, filtered.size()));
  const size_t compressed = libdeflate_zlib_compress(compressor, filtered.data(), filtered.size(),
                                                     zlib.data(), zlib.size());
  if (compressed == 0) return makeError("PNG encoding failed: deflate output too large");
  zlib.resize(compressed);

  std::vector<std::byte> png;
  png.reserve(compressed + 64);
  const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  for (uint8_t b : signature) png.push_back(std::byte{b});
  std::byte header[13];
  core::storeBigEndian32(&header[0], static_cast<uint32_t>(widthPixels));
  core::storeBigEndian32(&header[4], static_cast<uint32_t>(heightPixels));
  header[8] = std::byte{8};  // bits per channel
  // Grey, grey+alpha, RGB, RGBA.
  header[9] = std::byte{channels == 1 ? 0 : channels == 2 ? 4 : channels == 3 ? 2 : 6};
  header[10] = std::byte{0};  // deflate
  header[11] = std::byte{0};  // adaptive filtering
  header[12] = std::byte{0};  // not interlaced
  appendChunk(png, "IHDR", header);
  appendChunk(png, "IDAT", zlib);
  appendChunk(png, "IEND", {});
  return png;
}

// The pixels hold exactly width × height × channels bytes.
bool sized(size_t bytes, int widthPixels, int heightPixels, size_t channels) {
  return widthPixels > 0 && heightPixels > 0 &&
         bytes == channels * static_cast<size_t>(widthPixels) * static_cast<size_t>(heightPixels);
}

}  // namespace

Result<std::vector<std::byte>> encodePngRgba(std::span<const uint8_t> rgba, int widthPixels,
                                             int heightPixels) {
  if (!sized(rgba.size(), widthPixels, heightPixels, 4)) {
    return makeError("cannot encode PNG: malformed RGBA image");
  }
  return encodePngChannels<4>(rgba.data(), widthPixels, heightPixels);
}

Result<std::vector<std::byte>> encodePngRgb(std::span<const uint8_t> rgb, int widthPixels,
                                            int heightPixels, PngEncoding encoding) {
  if (!sized(rgb.size(), widthPixels, heightPixels, 3)) {
    return makeError("cannot encode PNG: malformed RGB image");
  }
  if (encoding.deflateLevel < 1 || encoding.deflateLevel > 12) {
    return makeError("cannot encode PNG: deflate level " + std::to_string(encoding.deflateLevel) +
                     " is not in 1..12");
  }
  return encodePngChannels<3>(rgb.data(), widthPixels, heightPixels, encoding);
}

Result<std::vector<std::byte>> encodePngGreyAlpha(std::span<const uint8_t> greyAlpha,
                                                  int widthPixels, int heightPixels) {
  if (!sized(greyAlpha.size(), widthPixels, heightPixels, 2)) {
    return makeError("cannot encode PNG: malformed grey+alpha image");
  }
  return encodePngChannels<2>(greyAlpha.data(), widthPixels, heightPixels);
}

}  // namespace globe::formats
