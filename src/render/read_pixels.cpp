// glReadPixels (bottom-up) flipped to top-down rows.
#include "render/read_pixels.hpp"

#include <algorithm>
#include <cstddef>

#include "render/gl.hpp"

namespace globe::render {

std::vector<uint8_t> readPixelsRgba(int widthPixels, int heightPixels) {
  if (widthPixels <= 0 || heightPixels <= 0) return {};
  const size_t rowBytes = static_cast<size_t>(widthPixels) * 4;
  const auto rows = static_cast<size_t>(heightPixels);
  std::vector<uint8_t> bottomUp(rowBytes * rows);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, widthPixels, heightPixels, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
  std::vector<uint8_t> topDown(bottomUp.size());
  for (size_t row = 0; row < rows; ++row) {
    const auto source = bottomUp.begin() + static_cast<std::ptrdiff_t>((rows - 1 - row) * rowBytes);
    std::copy(source, source + static_cast<std::ptrdiff_t>(rowBytes),
              topDown.begin() + static_cast<std::ptrdiff_t>(row * rowBytes));
  }
  return topDown;
}

void finishGl() { glFinish(); }

}  // namespace globe::render
