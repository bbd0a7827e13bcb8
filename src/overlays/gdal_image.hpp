// Images that stb_image does not read (GeoTIFF above all, as GroundOverlays of exported maps
// name them) decoded through GDAL's image drivers into RGBA8: grey, grey+alpha, palette, RGB and
// RGBA bands; other sample types clamped to 0..255.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "core/result.hpp"
#include "formats/image_io.hpp"

namespace globe::overlays {

// Refuses, before reading pixels, an image of more than maxDecodedBytes as RGBA8 or of a side
// beyond 32768. Errors name `name` and say why.
Result<formats::ImageRgba> decodeImageWithGdal(std::span<const std::byte> bytes,
                                               const std::string& name, uint64_t maxDecodedBytes);

}  // namespace globe::overlays
