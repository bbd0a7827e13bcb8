// Anti-aliasing by multisampling: the frame is drawn into an offscreen framebuffer with N samples
// a pixel (colour and depth), then resolved (averaged) into the context's own framebuffer, where
// the HUD is drawn sharp on top and pixels are read or swapped. The same for OSMesa (llvmpipe
// supports 2, 4 and 8) and a window, so snapshots, frames and video look alike.
#pragma once

#include <memory>

#include "core/result.hpp"
#include "render/gl_object.hpp"

namespace globe::render {

class MultisampleTarget {
 public:
  // Samples are clamped to what the GL offers (GL_MAX_SAMPLES): samples() says what was made.
  // Fails where the framebuffer cannot be made complete. Needs a current GL context.
  static Result<std::unique_ptr<MultisampleTarget>> create(int widthPixels, int heightPixels,
                                                           int samples);
  ~MultisampleTarget() = default;
  MultisampleTarget(const MultisampleTarget&) = delete;
  MultisampleTarget& operator=(const MultisampleTarget&) = delete;

  // Draws go to the multisampled buffers from now on.
  void bind() const;
  // Averages the samples into framebuffer 0 and binds it: draw the HUD, read or swap next.
  void resolve() const;
  // New size (a window resized): the buffers are made again.
  Result<void> resize(int widthPixels, int heightPixels);

  int samples() const { return samples_; }
  int widthPixels() const { return width_; }
  int heightPixels() const { return height_; }

 private:
  MultisampleTarget() = default;

  GlObject framebuffer_;
  GlObject colour_;
  GlObject depth_;
  int samples_ = 1;
  int width_ = 0;
  int height_ = 0;
};

// What --samples asks for: a target when samples > 1, else none (nullptr: draw straight into
// the context's framebuffer).
Result<std::unique_ptr<MultisampleTarget>> multisampleTargetFor(int widthPixels, int heightPixels,
                                                                int samples);

// The most samples the current GL offers for colour and depth (at least 1).
int maximumSamples();

}  // namespace globe::render
