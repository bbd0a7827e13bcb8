#include "render/multisample_target.hpp"

#include <algorithm>
#include <string>

namespace globe::render {
namespace {

GlObject makeFramebuffer() {
  GLuint name = 0;
  glGenFramebuffers(1, &name);
  return {name, [](GLuint n) { glDeleteFramebuffers(1, &n); }};
}

GlObject makeRenderbuffer(GLenum format, int samples, int width, int height) {
  GLuint name = 0;
  glGenRenderbuffers(1, &name);
  glBindRenderbuffer(GL_RENDERBUFFER, name);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  return {name, [](GLuint n) { glDeleteRenderbuffers(1, &n); }};
}

}  // namespace

int maximumSamples() {
  GLint most = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &most);
  return std::max(1, static_cast<int>(most));
}

Result<std::unique_ptr<MultisampleTarget>> MultisampleTarget::create(int widthPixels,
                                                                     int heightPixels,
                                                                     int samples) {
  std::unique_ptr<MultisampleTarget> target(new MultisampleTarget());
  target->samples_ = std::clamp(samples, 1, maximumSamples());
  if (auto made = target->resize(widthPixels, heightPixels); !made) return Error{made.error()};
  return target;
}

Result<std::unique_ptr<MultisampleTarget>> multisampleTargetFor(int widthPixels, int heightPixels,
                                                                int samples) {
  if (samples <= 1) return std::unique_ptr<MultisampleTarget>();
  return MultisampleTarget::create(widthPixels, heightPixels, samples);
}

Result<void> MultisampleTarget::resize(int widthPixels, int heightPixels) {
  width_ = widthPixels;
  height_ = heightPixels;
  framebuffer_ = makeFramebuffer();
  colour_ = makeRenderbuffer(GL_RGBA8, samples_, width_, height_);
  depth_ = makeRenderbuffer(GL_DEPTH_COMPONENT24, samples_, width_, height_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    return makeError("anti-aliasing: a " + std::to_string(width_) + "x" + std::to_string(height_) +
                     " framebuffer with " + std::to_string(samples_) +
                     " samples is not complete (GL status " + std::to_string(status) + ")");
  }
  return {};
}

void MultisampleTarget::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get()); }

void MultisampleTarget::resolve() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.get());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace globe::render
