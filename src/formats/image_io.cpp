// Image decoding with stb_image and PNG/JPEG encoding with stb_image_write (implementations come
// precompiled from libstb), written atomically.
#include "formats/image_io.hpp"

#include <stb_image.h>
#include <stb_image_write.h>
#include <webp/decode.h>

#include <cstddef>
#include <cstring>
#include <limits>
#include <string>

#include "formats/avif_image.hpp"
#include "formats/png_check.hpp"
#include "formats/png_encoder.hpp"
#include "formats/tile_edges.hpp"
#include "transport/atomic_file.hpp"

namespace globe::formats {
namespace {

constexpr uint64_t kMaxImageFileBytes = uint64_t{1} << 30;
constexpr uint64_t kMaxImagePixels = uint64_t{1} << 28;

void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::byte>*>(context);
  const auto* bytes = static_cast<const std::byte*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

bool wellFormed(const ImageRgba& image) {
  return image.widthPixels > 0 && image.heightPixels > 0 &&
         image.pixels.size() ==
             static_cast<size_t>(image.widthPixels) * static_cast<size_t>(image.heightPixels) * 4;
}

}  // namespace

namespace {

// "RIFF" size "WEBP": tile services' WebP (stb_image reads none).
bool isWebp(std::span<const std::byte> bytes) {
  return bytes.size() >= 12 && std::memcmp(bytes.data(), "RIFF", 4) == 0 &&
         std::memcmp(bytes.data() + 8, "WEBP", 4) == 0;
}

Result<ImageRgba> decodeWebp(std::span<const std::byte> bytes, const std::string& name) {
  const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
  int width = 0, height = 0;
  if (WebPGetInfo(data, bytes.size(), &width, &height) == 0) {
    return makeError(name + ": not a readable WebP image");
  }
  if (width <= 0 || height <= 0 || width > kMaxDecodedImageSide || height > kMaxDecodedImageSide) {
    return makeError(name + ": image size " + std::to_string(width) + "x" + std::to_string(height) +
                     " out of range 1.." + std::to_string(kMaxDecodedImageSide));
  }
  ImageRgba image;
  image.widthPixels = width;
  image.heightPixels = height;
  image.pixels.resize(static_cast<size_t>(width) * height * 4);
  if (WebPDecodeRGBAInto(data, bytes.size(), image.pixels.data(), image.pixels.size(), width * 4) ==
      nullptr) {
    return makeError(name + ": cannot decode WebP image");
  }
  return image;
}

}  // namespace

Result<ImageRgba> decodeImageRgba(std::span<const std::byte> bytes, const std::string& name) {
  if (bytes.size() > static_cast<size_t>(std::numeric_limits<int>::max())) {
    return makeError(name + ": image too large");
  }
  if (isWebp(bytes)) return decodeWebp(bytes, name);
  if (isAvif(bytes)) return decodeAvif(bytes, name);
  if (auto png = checkPngStructure(bytes, name); !png) return Error{png.error()};
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = static_cast<int>(bytes.size());
  int width = 0, height = 0, channels = 0;
  if (stbi_info_from_memory(data, size, &width, &height, &channels) == 0) {
    return makeError(name + ": not a readable image: " + stbi_failure_reason());
  }
  if (width <= 0 || height <= 0 || width > kMaxDecodedImageSide || height > kMaxDecodedImageSide) {
    return makeError(name + ": image size " + std::to_string(width) + "x" + std::to_string(height) +
                     " out of range 1.." + std::to_string(kMaxDecodedImageSide));
  }
  stbi_uc* decoded = stbi_load_from_memory(data, size, &width, &height, &channels, 4);
  if (decoded == nullptr)
    return makeError(name + ": cannot decode image: " + stbi_failure_reason());
  ImageRgba image;
  image.widthPixels = width;
  image.heightPixels = height;
  image.pixels.assign(decoded, decoded + static_cast<size_t>(width) * height * 4);
  stbi_image_free(decoded);
  restoreTileEdges(bytes, image);  // a JPEG tile's exact edge samples, when it carries them
  return image;
}

Result<std::vector<std::byte>> encodeJpeg(const ImageRgba& image, int quality) {
  if (!wellFormed(image)) return makeError("cannot encode JPEG: malformed RGBA image");
  if (quality < 1 || quality > 100) return makeError("JPEG quality must be 1..100");
  std::vector<std::byte> jpeg;
  if (stbi_write_jpg_to_func(appendBytes, &jpeg, image.widthPixels, image.heightPixels, 4,
                             image.pixels.data(), quality) == 0) {
    return makeError("JPEG encoding failed");
  }
  return jpeg;
}

Result<std::vector<std::byte>> encodePng(const ImageRgba& image) {
  if (!wellFormed(image)) return makeError("cannot encode PNG: malformed RGBA image");
  return encodePngRgba(image.pixels, image.widthPixels, image.heightPixels);
}

Result<ImageRgba> loadImageRgba(const std::filesystem::path& path) {
  auto bytes = transport::readWholeFile(path, kMaxImageFileBytes);
  if (!bytes) return makeError(bytes.error());
  if (bytes->size() > static_cast<size_t>(std::numeric_limits<int>::max())) {
    return makeError(path.string() + ": image file too large");
  }
  if (auto png = checkPngStructure(*bytes, path.string()); !png) return Error{png.error()};
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes->data());
  const int size = static_cast<int>(bytes->size());
  int width = 0, height = 0, channels = 0;
  if (stbi_info_from_memory(data, size, &width, &height, &channels) == 0) {
    return makeError(path.string() + ": not a readable image: " + stbi_failure_reason());
  }
  if (width <= 0 || height <= 0 ||
      static_cast<uint64_t>(width) * static_cast<uint64_t>(height) > kMaxImagePixels) {
    return makeError(path.string() + ": image size " + std::to_string(width) + "x" +
                     std::to_string(height) + " out of range");
  }
  stbi_uc* decoded = stbi_load_from_memory(data, size, &width, &height, &channels, 4);
  if (decoded == nullptr) {
    return makeError(path.string() + ": cannot decode image: " + stbi_failure_reason());
  }
  ImageRgba image;
  image.widthPixels = width;
  image.heightPixels = height;
  const size_t count = static_cast<size_t>(width) * static_cast<size_t>(height) * 4;
  image.pixels.assign(decoded, decoded + count);
  stbi_image_free(decoded);
  return image;
}

Result<void> writePngAtomically(const std::filesystem::path& path, std::span<const uint8_t> rgba,
                                int widthPixels, int heightPixels) {
  if (widthPixels <= 0 || heightPixels <= 0 ||
      rgba.size() != static_cast<size_t>(widthPixels) * static_cast<size_t>(heightPixels) * 4) {
    return makeError(path.string() + ": cannot write PNG: " + std::to_string(rgba.size()) +
                     " bytes do not make a " + std::to_string(widthPixels) + "x" +
                     std::to_string(heightPixels) + " RGBA image");
  }
  auto png = encodePngRgba(rgba, widthPixels, heightPixels);
  if (!png) return makeError(path.string() + ": " + png.error());
  return transport::writeFileAtomically(path, std::span<const std::byte>(*png));
}

}  // namespace globe::formats
