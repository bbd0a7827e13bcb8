#include "compression/gzip_bytes.hpp"

#include <libdeflate.h>

#include <memory>

namespace globe::compression {
namespace {

struct GzipDecompressorDeleter {
  void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
};

}  // namespace

bool isGzip(std::span<const std::byte> bytes) {
  return bytes.size() >= 2 && bytes[0] == std::byte{0x1f} && bytes[1] == std::byte{0x8b};
}

Result<std::vector<std::byte>> gunzipIfNeeded(std::span<const std::byte> bytes,
                                              const std::string& name, size_t maxBytes) {
  if (!isGzip(bytes)) return std::vector<std::byte>(bytes.begin(), bytes.end());
  thread_local std::unique_ptr<libdeflate_decompressor, GzipDecompressorDeleter> decompressor(
      libdeflate_alloc_decompressor());
  if (!decompressor) return makeError(name + ": out of memory inflating gzip");
  // gzip's trailer states the size modulo 2^32: a start, grown when it lies.
  size_t capacity = std::min<size_t>(maxBytes, std::max<size_t>(bytes.size() * 4, 4096));
  for (;;) {
    std::vector<std::byte> out(capacity);
    size_t inflated = 0;
    const libdeflate_result r = libdeflate_gzip_decompress(
        decompressor.get(), bytes.data(), bytes.size(), out.data(), out.size(), &inflated);
    if (r == LIBDEFLATE_SUCCESS) {
      out.resize(inflated);
      return out;
    }
    if (r != LIBDEFLATE_INSUFFICIENT_SPACE) return makeError(name + ": a damaged gzip stream");
    if (capacity >= maxBytes) {
      return makeError(name + ": inflates to more than " + std::to_string(maxBytes) + " bytes");
    }
    capacity = std::min(maxBytes, capacity * 4);
  }
}

}  // namespace globe::compression
