// A first draw with a throw-away program: on llvmpipe the first program drawn in a context stays
// ~9 ms/frame slower for the whole run, so contexts spend that on a program nobody keeps.
#pragma once

#include "core/result.hpp"

namespace globe::render {

// Draws one triangle into the current framebuffer with a trivial program, then clears colour and
// depth and deletes everything it made. Needs loaded GL functions (loadGlFunctions).
Result<void> warmUpGl();

}  // namespace globe::render
