#include "publish/imagery_tile_encoding.hpp"

#include <webp/encode.h>

#include <algorithm>

namespace globe::publish {
namespace {

Result<std::vector<std::byte>> encodeWebp(const formats::ImageRgba& image, int quality) {
  uint8_t* output = nullptr;
  const size_t size = WebPEncodeRGBA(image.pixels.data(), image.widthPixels, image.heightPixels,
                                     image.widthPixels * 4,
                                     static_cast<float>(std::clamp(quality, 1, 100)), &output);
  if (size == 0 || output == nullptr) {
    WebPFree(output);
    return makeError("cannot encode a " + std::to_string(image.widthPixels) + "×" +
                     std::to_string(image.heightPixels) + " WebP image");
  }
  const auto* first = reinterpret_cast<const std::byte*>(output);
  std::vector<std::byte> bytes(first, first + size);
  WebPFree(output);
  return bytes;
}

}  // namespace

std::optional<ImageryTileFormat> imageryTileFormatNamed(std::string_view name) {
  if (name == "png") return ImageryTileFormat::Png;
  if (name == "jpeg" || name == "jpg") return ImageryTileFormat::Jpeg;
  if (name == "webp") return ImageryTileFormat::Webp;
  return std::nullopt;
}

const char* extensionOf(ImageryTileFormat format) {
  switch (format) {
    case ImageryTileFormat::Png:
      return "png";
    case ImageryTileFormat::Jpeg:
      return "jpg";
    case ImageryTileFormat::Webp:
      return "webp";
  }
  return "png";
}

const char* mimeTypeOf(ImageryTileFormat format) {
  switch (format) {
    case ImageryTileFormat::Png:
      return "image/png";
    case ImageryTileFormat::Jpeg:
      return "image/jpeg";
    case ImageryTileFormat::Webp:
      return "image/webp";
  }
  return "image/png";
}

Result<std::vector<std::byte>> encodeImageryTile(const formats::ImageRgba& image,
                                                 ImageryTileFormat format, int quality) {
  switch (format) {
    case ImageryTileFormat::Png:
      return formats::encodePng(image);
    case ImageryTileFormat::Jpeg:
      return formats::encodeJpeg(image, std::clamp(quality, 1, 100));
    case ImageryTileFormat::Webp:
      return encodeWebp(image, quality);
  }
  return formats::encodePng(image);
}

}  // namespace globe::publish
