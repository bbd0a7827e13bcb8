// Texture uploads from tightly packed rows, whatever unpack state the caller left.
#pragma once

#include "render/gl.hpp"

namespace globe::render {

// While it lives: 1-byte row alignment (rows of 2-byte texels need not be 4-aligned) and rows of
// rowTexels texels (0: as wide as the upload). The caller's state is restored after.
class TightUnpack {
 public:
  explicit TightUnpack(int rowTexels = 0) {
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment_);
    glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, rowTexels);
  }
  ~TightUnpack() {
    glPixelStorei(GL_UNPACK_ROW_LENGTH, rowLength_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment_);
  }
  TightUnpack(const TightUnpack&) = delete;
  TightUnpack& operator=(const TightUnpack&) = delete;

 private:
  GLint alignment_ = 4, rowLength_ = 0;
};

}  // namespace globe::render
