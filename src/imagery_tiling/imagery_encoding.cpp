#include "imagery_tiling/imagery_encoding.hpp"

// clang-format off
#include <cstdio>  // jpeglib.h needs FILE first
#include <jpeglib.h>
// clang-format on
#include <libdeflate.h>

#include <csetjmp>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "formats/png_encoder.hpp"
#include "formats/tile_edges.hpp"

namespace globe::imagery_tiling {
namespace {

bool wellFormed(const formats::ImageRgba& image) {
  return image.widthPixels > 0 && image.heightPixels > 0 &&
         image.pixels.size() == size_t(image.widthPixels) * size_t(image.heightPixels) * 4;
}

// libjpeg reports errors by calling error_exit, which must not return: jump back instead.
struct JpegError {
  jpeg_error_mgr manager;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void onJpegError(j_common_ptr info) {
  auto* error = reinterpret_cast<JpegError*>(info->err);
  (*info->err->format_message)(info, error->message);
  std::longjmp(error->jump, 1);
}

struct CompressorDeleter {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

}  // namespace

Result<std::vector<std::byte>> encodeJpegFast(const formats::ImageRgba& image, int quality,
                                              bool exactEdges) {
  if (!wellFormed(image)) return makeError("cannot encode JPEG: malformed RGBA image");
  if (quality < 1 || quality > 100) return makeError("JPEG quality must be 1..100");
  std::vector<std::byte> edges;
  if (exactEdges) {
    const std::vector<uint8_t> ring = formats::tileEdgeBytes(image);
    edges = formats::tileEdgesHead(image.widthPixels, image.heightPixels);
    thread_local std::unique_ptr<libdeflate_compressor, CompressorDeleter> compressor(
        libdeflate_alloc_compressor(9));
    if (!compressor) return makeError("JPEG encoding failed: cannot allocate a compressor");
    const size_t head = edges.size();
    edges.resize(head + libdeflate_zlib_compress_bound(compressor.get(), ring.size()));
    const size_t compressed = libdeflate_zlib_compress(compressor.get(), ring.data(), ring.size(),
                                                       &edges[head], edges.size() - head);
    if (compressed == 0 || head + compressed > 65533) {
      return makeError("JPEG encoding failed: the edge segment does not fit");
    }
    edges.resize(head + compressed);
  }
  jpeg_compress_struct info{};
  JpegError error{};
  info.err = jpeg_std_error(&error.manager);
  error.manager.error_exit = onJpegError;
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  if (setjmp(error.jump) != 0) {
    jpeg_destroy_compress(&info);
    std::free(buffer);
    return makeError(std::string("JPEG encoding failed: ") + error.message);
  }
  jpeg_create_compress(&info);
  jpeg_mem_dest(&info, &buffer, &size);
  info.image_width = static_cast<JDIMENSION>(image.widthPixels);
  info.image_height = static_cast<JDIMENSION>(image.heightPixels);
  info.input_components = 4;
  info.in_color_space = JCS_EXT_RGBX;  // libjpeg-turbo reads RGBA, skipping the alpha byte
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, quality, TRUE);
  info.dct_method = JDCT_ISLOW;
  jpeg_start_compress(&info, TRUE);
  if (!edges.empty()) {
    jpeg_write_marker(&info, formats::kTileEdgesMarker,
                      reinterpret_cast<const JOCTET*>(edges.data()),
                      static_cast<unsigned int>(edges.size()));
  }
  const auto stride = static_cast<size_t>(image.widthPixels) * 4;
  while (info.next_scanline < info.image_height) {
    auto* row = const_cast<JSAMPROW>(&image.pixels[info.next_scanline * stride]);
    jpeg_write_scanlines(&info, &row, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  std::vector<std::byte> out(size);
  std::memcpy(out.data(), buffer, size);
  std::free(buffer);
  return out;
}

Result<std::vector<std::byte>> encodePngFast(const formats::ImageRgba& image) {
  if (!wellFormed(image)) return makeError("cannot encode PNG: malformed RGBA image");
  return formats::encodePngRgba(image.pixels, image.widthPixels, image.heightPixels);
}

Result<std::vector<std::byte>> encodePngGreyAlphaFast(std::span<const uint8_t> greyAlpha,
                                                      int widthPixels, int heightPixels) {
  return formats::encodePngGreyAlpha(greyAlpha, widthPixels, heightPixels);
}

}  // namespace globe::imagery_tiling
