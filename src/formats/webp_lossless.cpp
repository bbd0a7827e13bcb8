#include "formats/webp_lossless.hpp"

#include <webp/encode.h>

#include <cstdint>
#include <string>

namespace globe::formats {

Result<std::vector<std::byte>> encodeWebpLossless(const ImageRgba& image) {
  const size_t pixels = static_cast<size_t>(image.widthPixels) * image.heightPixels;
  if (image.widthPixels <= 0 || image.heightPixels <= 0 || image.pixels.size() != pixels * 4) {
    return makeError("WebP: an image of " + std::to_string(image.widthPixels) + "×" +
                     std::to_string(image.heightPixels) + " pixels holding " +
                     std::to_string(image.pixels.size()) + " bytes");
  }
  std::vector<uint8_t> rgb(pixels * 3);
  for (size_t p = 0; p < pixels; ++p) {
    for (size_t c = 0; c < 3; ++c) rgb[p * 3 + c] = image.pixels[p * 4 + c];
  }
  uint8_t* out = nullptr;
  const size_t size = WebPEncodeLosslessRGB(rgb.data(), image.widthPixels, image.heightPixels,
                                            image.widthPixels * 3, &out);
  if (size == 0 || out == nullptr) {
    WebPFree(out);
    return makeError("WebP: libwebp could not encode a " + std::to_string(image.widthPixels) + "×" +
                     std::to_string(image.heightPixels) + " image");
  }
  std::vector<std::byte> bytes(reinterpret_cast<const std::byte*>(out),
                               reinterpret_cast<const std::byte*>(out) + size);
  WebPFree(out);
  return bytes;
}

}  // namespace globe::formats
