// Read-back of the current framebuffer as RGBA8 rows top-down (ready for PNG writing).
#pragma once

#include <cstdint>
#include <vector>

namespace globe::render {

// Reads the colour of the current context's framebuffer (a window's back buffer), the rectangle
// (0, 0)–(width, height), after the GL commands before it finish. Rows top-down, 4 bytes a pixel.
std::vector<uint8_t> readPixelsRgba(int widthPixels, int heightPixels);

// Blocks until every GL command issued so far has completed (glFinish), e.g. to time frames.
void finishGl();

}  // namespace globe::render
