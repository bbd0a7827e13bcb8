// AVIF images (AV1 stills in an ISO-BMFF box structure), as PMTiles archives and WMTS servers
// serve imagery, decoded with Debian's libavif (dav1d or libaom underneath).
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "core/result.hpp"
#include "formats/image_io.hpp"

namespace globe::formats {

// An ISO-BMFF "ftyp" box whose major or compatible brands name an AVIF image or sequence.
bool isAvif(std::span<const std::byte> bytes);

// The first image of an AVIF file as 8-bit RGBA (alpha 255 where it has none). Errors name `name`;
// images over kMaxDecodedImageSide on a side are refused before their pixels are decoded.
Result<ImageRgba> decodeAvif(std::span<const std::byte> bytes, const std::string& name);

}  // namespace globe::formats
