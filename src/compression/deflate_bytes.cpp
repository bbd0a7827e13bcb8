#include "compression/deflate_bytes.hpp"

#include <libdeflate.h>

#include <array>
#include <memory>

namespace globe::compression {
namespace {

struct CompressorDeleter {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};
struct DecompressorDeleter {
  void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
};
using Compressor = std::unique_ptr<libdeflate_compressor, CompressorDeleter>;

libdeflate_compressor* compressorAt(int level) {
  constexpr int kLevels = 12;
  thread_local std::array<Compressor, kLevels + 1> compressors;
  const int clamped = level < 1 ? 1 : level > kLevels ? kLevels : level;
  Compressor& slot = compressors[static_cast<size_t>(clamped)];
  if (!slot) slot.reset(libdeflate_alloc_compressor(clamped));
  return slot.get();
}

libdeflate_decompressor* decompressor() {
  thread_local std::unique_ptr<libdeflate_decompressor, DecompressorDeleter> d(
      libdeflate_alloc_decompressor());
  return d.get();
}

}  // namespace

std::vector<std::byte> zlibCompress(std::span<const std::byte> in, int level) {
  libdeflate_compressor* c = compressorAt(level);
  std::vector<std::byte> out(libdeflate_zlib_compress_bound(c, in.size()));
  out.resize(libdeflate_zlib_compress(c, in.data(), in.size(), out.data(), out.size()));
  return out;
}

std::vector<std::byte> deflateCompress(std::span<const std::byte> in, int level) {
  libdeflate_compressor* c = compressorAt(level);
  std::vector<std::byte> out(libdeflate_deflate_compress_bound(c, in.size()));
  out.resize(libdeflate_deflate_compress(c, in.data(), in.size(), out.data(), out.size()));
  return out;
}

std::vector<std::byte> gzipCompress(std::span<const std::byte> in, int level) {
  libdeflate_compressor* c = compressorAt(level);
  std::vector<std::byte> out(libdeflate_gzip_compress_bound(c, in.size()));
  out.resize(libdeflate_gzip_compress(c, in.data(), in.size(), out.data(), out.size()));
  return out;
}

bool zlibInflateExactly(std::span<const std::byte> in, std::span<std::byte> out) {
  size_t actual = 0;
  return libdeflate_zlib_decompress(decompressor(), in.data(), in.size(), out.data(), out.size(),
                                    &actual) == LIBDEFLATE_SUCCESS &&
         actual == out.size();
}

bool deflateInflateExactly(std::span<const std::byte> in, std::span<std::byte> out) {
  size_t actual = 0;
  return libdeflate_deflate_decompress(decompressor(), in.data(), in.size(), out.data(), out.size(),
                                       &actual) == LIBDEFLATE_SUCCESS &&
         actual == out.size();
}

}  // namespace globe::compression
