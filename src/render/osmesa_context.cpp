// OSMesa context creation through OSMesaCreateContextAttribs (asking 3.3 core gives 4.5 core).
#include "render/osmesa_context.hpp"

#include <GL/osmesa.h>

#include <string>

#include "render/gl_loader.hpp"
#include "render/gl_warm_up.hpp"

namespace globe::render {
namespace {

constexpr int kMaxSidePixels = 16384;

Result<void> checkSize(int widthPixels, int heightPixels) {
  if (widthPixels < 1 || heightPixels < 1 || widthPixels > kMaxSidePixels ||
      heightPixels > kMaxSidePixels) {
    return makeError("OSMesa: framebuffer size " + std::to_string(widthPixels) + "x" +
                     std::to_string(heightPixels) + " out of range 1.." +
                     std::to_string(kMaxSidePixels));
  }
  return {};
}

}  // namespace

OsMesaContext::OsMesaContext(osmesa_context* context, int widthPixels, int heightPixels)
    : context_(context), width_(widthPixels), height_(heightPixels) {}

OsMesaContext::~OsMesaContext() {
  if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(context_);
}

Result<std::unique_ptr<OsMesaContext>> OsMesaContext::create(int widthPixels, int heightPixels) {
  if (auto size = checkSize(widthPixels, heightPixels); !size) return makeError(size.error());
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            24,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_ACCUM_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  OSMesaContext raw = OSMesaCreateContextAttribs(attributes, nullptr);
  if (raw == nullptr) {
    return makeError(
        "OSMesa: OSMesaCreateContextAttribs failed for a 3.3 core RGBA8 + depth24 "
        "context");
  }
  std::unique_ptr<OsMesaContext> context(new OsMesaContext(raw, widthPixels, heightPixels));
  if (auto bound = context->bindBuffer(); !bound) return makeError(bound.error());
  if (auto warm = warmUpGl(); !warm) return makeError(warm.error());
  return context;
}

Result<void> OsMesaContext::bindBuffer() {
  buffer_.assign(static_cast<size_t>(width_) * static_cast<size_t>(height_) * 4, 0);
  if (OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_) != GL_TRUE) {
    return makeError("OSMesa: OSMesaMakeCurrent failed for " + std::to_string(width_) + "x" +
                     std::to_string(height_));
  }
  return loadGlFunctions(OSMesaGetProcAddress);
}

Result<void> OsMesaContext::makeCurrent() {
  if (OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_) != GL_TRUE) {
    return makeError("OSMesa: OSMesaMakeCurrent failed");
  }
  return loadGlFunctions(OSMesaGetProcAddress);
}

Result<void> OsMesaContext::resize(int widthPixels, int heightPixels) {
  if (auto size = checkSize(widthPixels, heightPixels); !size) return size;
  width_ = widthPixels;
  height_ = heightPixels;
  return bindBuffer();
}

}  // namespace globe::render
