// AVIF files for tests, made with libavif's encoder (libaom): the decoder's tests and those of the
// services that serve AVIF tiles need real AVIF bytes, and ../shared/data holds none.
#pragma once

#include <cstddef>
#include <vector>

#include "formats/image_io.hpp"

namespace globe::testing {

// Lossless (identity matrix, 4:4:4, quantizer 0): the decoded RGB equals the image's; alpha kept.
// Empty on failure (the test then fails on it).
std::vector<std::byte> encodeAvifLossless(const formats::ImageRgba& image);

}  // namespace globe::testing
