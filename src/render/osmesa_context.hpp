// A headless GL 3.3 core context (Mesa's OSMesa, llvmpipe): RGBA8 colour + 24-bit depth in memory.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/result.hpp"

struct osmesa_context;  // OSMesa's opaque context (GL/osmesa.h stays out of this header)

namespace globe::render {

class OsMesaContext {
 public:
  // Creates the context, makes it current on this thread, loads the GL functions and does the
  // warm-up draw. Sizes from 1 to 16384 pixels per side.
  static Result<std::unique_ptr<OsMesaContext>> create(int widthPixels, int heightPixels);
  ~OsMesaContext();
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  // Makes this context current on the calling thread (and reloads the GL function pointers).
  Result<void> makeCurrent();
  // New framebuffer size; the context's GL objects survive. Makes the context current.
  Result<void> resize(int widthPixels, int heightPixels);

  int widthPixels() const { return width_; }
  int heightPixels() const { return height_; }

 private:
  OsMesaContext(osmesa_context* context, int widthPixels, int heightPixels);
  Result<void> bindBuffer();

  osmesa_context* context_;
  int width_;
  int height_;
  std::vector<uint8_t> buffer_;  // the colour buffer OSMesa renders into, bottom row first
};

}  // namespace globe::render
