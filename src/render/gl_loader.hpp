// Loads the GL function pointers (glad2) for the current context, whichever made it.
#pragma once

#include <string>

#include "core/result.hpp"

namespace globe::render {

// A context API's "get proc address": OSMesaGetProcAddress and glfwGetProcAddress both fit.
using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name);

// Loads every GL 3.3 core function through `loader` for the context current on this thread and
// checks that the context really is 3.3 or newer. The pointers are process-wide (glad's), so a
// process should use one kind of context at a time; contexts call this when made current.
Result<void> loadGlFunctions(GlProcLoader loader);

// What the current context is (after loadGlFunctions).
struct GlInfo {
  int major = 0;
  int minor = 0;
  std::string version;   // GL_VERSION
  std::string renderer;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string vendor;    // GL_VENDOR
};
GlInfo currentGlInfo();

}  // namespace globe::render
