// Draws one RGBA image over the frame at a rectangle in window pixels (y down), pixel for pixel:
// the elevation chart in `globe view`'s corner.
#pragma once

#include <filesystem>
#include <memory>

#include <glm/vec2.hpp>

#include "core/result.hpp"
#include "formats/image_io.hpp"

namespace globe::render {

// Needs a current GL 3.3 core context for its whole life, like HudRenderer.
class ImageOverlay {
 public:
  // Loads <shaderDirectory>/image.vert and image.frag (empty: defaultShaderDirectory(), embedded).
  static Result<std::unique_ptr<ImageOverlay>> create(const std::filesystem::path& shaderDirectory);
  ~ImageOverlay();
  ImageOverlay(const ImageOverlay&) = delete;
  ImageOverlay& operator=(const ImageOverlay&) = delete;

  // Uploads the image (straight alpha, rows top-down), replacing the last; an image whose pixels
  // do not match its size clears it.
  void setImage(const formats::ImageRgba& image);
  bool hasImage() const;
  glm::ivec2 sizePixels() const;

  // Blends the image, its alpha times opacity, at topLeftPixels of the current framebuffer's
  // (0, 0, width, height) viewport, without depth test; leaves depth test and culling enabled and
  // blending disabled, as HudRenderer does.
  void draw(glm::vec2 topLeftPixels, int widthPixels, int heightPixels, float opacity = 1.0f) const;

 private:
  struct Impl;
  explicit ImageOverlay(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace globe::render
