// Move-only owner of one GL object name (buffer, vertex array, texture, shader, program).
#pragma once

#include <utility>

#include "render/gl.hpp"

namespace globe::render {

class GlObject {
 public:
  using Deleter = void (*)(GLuint name);

  GlObject() = default;
  GlObject(GLuint name, Deleter deleter) : name_(name), deleter_(deleter) {}
  GlObject(GlObject&& other) noexcept
      : name_(std::exchange(other.name_, 0u)), deleter_(other.deleter_) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      reset();
      name_ = std::exchange(other.name_, 0u);
      deleter_ = other.deleter_;
    }
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  ~GlObject() { reset(); }

  GLuint get() const { return name_; }
  explicit operator bool() const { return name_ != 0; }
  // Deletes the object (the context it belongs to must be current).
  void reset() {
    if (name_ != 0 && deleter_ != nullptr) deleter_(name_);
    name_ = 0;
  }

 private:
  GLuint name_ = 0;
  Deleter deleter_ = nullptr;
};

inline GlObject makeGlBuffer() {
  GLuint name = 0;
  glGenBuffers(1, &name);
  return {name, [](GLuint n) { glDeleteBuffers(1, &n); }};
}
inline GlObject makeGlVertexArray() {
  GLuint name = 0;
  glGenVertexArrays(1, &name);
  return {name, [](GLuint n) { glDeleteVertexArrays(1, &n); }};
}
inline GlObject makeGlTexture() {
  GLuint name = 0;
  glGenTextures(1, &name);
  return {name, [](GLuint n) { glDeleteTextures(1, &n); }};
}
inline GlObject makeGlShader(GLenum type) {
  return {glCreateShader(type), [](GLuint n) { glDeleteShader(n); }};
}
inline GlObject makeGlSampler() {
  GLuint name = 0;
  glGenSamplers(1, &name);
  return {name, [](GLuint n) { glDeleteSamplers(1, &n); }};
}
inline GlObject makeGlProgram() {
  return {glCreateProgram(), [](GLuint n) { glDeleteProgram(n); }};
}

}  // namespace globe::render
