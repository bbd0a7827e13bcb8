// AVIF decoding through libavif: the header first (so an oversized image costs nothing), one
// thread (the loader runs many tiles at once), Exif and XMP skipped.
#include "formats/avif_image.hpp"

#include <avif/avif.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>

#include "core/big_endian.hpp"

namespace globe::formats {
namespace {

constexpr const char* kAvifBrands[] = {"avif", "avis"};

bool isAvifBrand(const std::byte* p) {
  for (const char* brand : kAvifBrands) {
    if (std::memcmp(p, brand, 4) == 0) return true;
  }
  return false;
}

struct DecoderDeleter {
  void operator()(avifDecoder* decoder) const { avifDecoderDestroy(decoder); }
};

}  // namespace

bool isAvif(std::span<const std::byte> bytes) {
  if (bytes.size() < 16 || std::memcmp(bytes.data() + 4, "ftyp", 4) != 0) return false;
  const size_t boxBytes = std::min<size_t>(core::loadBigEndian32(bytes.data()), bytes.size());
  if (isAvifBrand(bytes.data() + 8)) return true;
  for (size_t at = 16; at + 4 <= boxBytes; at += 4) {  // the compatible brands
    if (isAvifBrand(bytes.data() + at)) return true;
  }
  return false;
}

Result<ImageRgba> decodeAvif(std::span<const std::byte> bytes, const std::string& name) {
  std::unique_ptr<avifDecoder, DecoderDeleter> decoder(avifDecoderCreate());
  if (!decoder) return makeError(name + ": cannot make an AVIF decoder");
  decoder->maxThreads = 1;
  decoder->ignoreExif = AVIF_TRUE;
  decoder->ignoreXMP = AVIF_TRUE;
  decoder->imageSizeLimit = static_cast<uint32_t>(kMaxDecodedImageSide) * kMaxDecodedImageSide;
  decoder->imageDimensionLimit = static_cast<uint32_t>(kMaxDecodedImageSide);
  decoder->imageCountLimit = 1;  // an image sequence: its first frame only
  const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
  avifResult result = avifDecoderSetIOMemory(decoder.get(), data, bytes.size());
  if (result == AVIF_RESULT_OK) result = avifDecoderParse(decoder.get());
  if (result != AVIF_RESULT_OK) {
    return makeError(name + ": not a readable AVIF image: " + avifResultToString(result));
  }
  const uint32_t width = decoder->image->width, height = decoder->image->height;
  if (width == 0 || height == 0 || width > static_cast<uint32_t>(kMaxDecodedImageSide) ||
      height > static_cast<uint32_t>(kMaxDecodedImageSide)) {
    return makeError(name + ": image size " + std::to_string(width) + "x" + std::to_string(height) +
                     " out of range 1.." + std::to_string(kMaxDecodedImageSide));
  }
  result = avifDecoderNextImage(decoder.get());
  if (result != AVIF_RESULT_OK) {
    return makeError(name + ": cannot decode AVIF image: " + avifResultToString(result));
  }
  ImageRgba image;
  image.widthPixels = static_cast<int>(width);
  image.heightPixels = static_cast<int>(height);
  image.pixels.resize(static_cast<size_t>(width) * height * 4);
  avifRGBImage rgb;
  avifRGBImageSetDefaults(&rgb, decoder->image);
  rgb.format = AVIF_RGB_FORMAT_RGBA;
  rgb.depth = 8;
  rgb.pixels = image.pixels.data();
  rgb.rowBytes = width * 4;
  result = avifImageYUVToRGB(decoder->image, &rgb);
  if (result != AVIF_RESULT_OK) {
    return makeError(name + ": cannot convert AVIF image to RGB: " + avifResultToString(result));
  }
  return image;
}

}  // namespace globe::formats
