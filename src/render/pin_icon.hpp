// The built-in placemark icon, drawn procedurally so labels need no image file.
#pragma once

#include "formats/image_io.hpp"

namespace globe::render {

// A white-filled disc with a dark rim, anti-aliased, on a transparent square (straight alpha).
formats::ImageRgba makePinIcon(int sidePixels = 64);

}  // namespace globe::render
