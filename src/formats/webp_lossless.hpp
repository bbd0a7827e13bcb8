// Lossless WebP out (libwebp), for elevation tiles whose colours are heights: any lossy step
// would change them. Read back by decodeImageRgba (image_io.hpp).
#pragma once

#include <cstddef>
#include <vector>

#include "core/result.hpp"
#include "formats/image_io.hpp"

namespace globe::formats {

// Encodes the image's RGB (alpha dropped: elevation tiles are opaque), every pixel kept exactly.
Result<std::vector<std::byte>> encodeWebpLossless(const ImageRgba& image);

}  // namespace globe::formats
