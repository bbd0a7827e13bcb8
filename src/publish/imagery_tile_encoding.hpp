// The image formats web maps read, for exported imagery tiles: PNG (lossless, with alpha), JPEG
// (opaque; transparent pixels come out black) and WebP (lossy, with alpha).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.hpp"
#include "formats/image_io.hpp"

namespace globe::publish {

enum class ImageryTileFormat { Png, Jpeg, Webp };

// "png", "jpeg" (or "jpg"), "webp"; nullopt otherwise.
std::optional<ImageryTileFormat> imageryTileFormatNamed(std::string_view name);
// The files' extension without its dot ("png", "jpg", "webp").
const char* extensionOf(ImageryTileFormat format);
const char* mimeTypeOf(ImageryTileFormat format);

// quality 1..100 for JPEG and WebP; PNG ignores it.
Result<std::vector<std::byte>> encodeImageryTile(const formats::ImageRgba& image,
                                                 ImageryTileFormat format, int quality);

}  // namespace globe::publish
