// The pin: coverage from each pixel centre's distance to the disc's edge (a one-pixel ramp), so
// the icon stays smooth when mipmapped down to label sizes.
#include "render/pin_icon.hpp"

#include <algorithm>
#include <cmath>

namespace globe::render {

formats::ImageRgba makePinIcon(int sidePixels) {
  formats::ImageRgba image;
  const int side = std::max(sidePixels, 4);
  image.widthPixels = side;
  image.heightPixels = side;
  image.pixels.assign(static_cast<size_t>(4 * side * side), 0);
  const float centre = 0.5f * static_cast<float>(side);
  const float radius = centre - 1.0f;
  const float rim = std::max(1.5f, 0.14f * static_cast<float>(side));
  constexpr float kRimGrey = 40.0f;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const float distance =
          std::hypot(static_cast<float>(x) + 0.5f - centre, static_cast<float>(y) + 0.5f - centre);
      const float alpha = std::clamp(radius - distance + 0.5f, 0.0f, 1.0f);
      const float white = std::clamp(radius - rim - distance + 0.5f, 0.0f, 1.0f);
      const float grey = kRimGrey + (255.0f - kRimGrey) * white;
      uint8_t* pixel = &image.pixels[static_cast<size_t>(4 * (y * side + x))];
      pixel[0] = pixel[1] = pixel[2] = static_cast<uint8_t>(std::lround(grey));
      pixel[3] = static_cast<uint8_t>(std::lround(255.0f * alpha));
    }
  }
  return image;
}

}  // namespace globe::render
