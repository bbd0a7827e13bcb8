// Draws the HUD over the frame in window pixels (y down): blocks of lines built from
// stb_easy_font's quads (no font file), each on a translucent box, and flat shapes (the compass
// rose, the scale bar), in the order given.
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/result.hpp"

namespace globe::render {

struct HudTextBlock {
  std::vector<std::string> lines;
  glm::vec2 topLeftPixels{8.0f, 8.0f};  // of the box, window pixels from the top-left corner
  float scale = 1.0f;                   // screen pixels per font pixel (a line is 12 font pixels)
  float paddingPixels = 5.0f;
  glm::vec4 textRgba{1.0f, 1.0f, 1.0f, 1.0f};
  glm::vec4 backgroundRgba{0.0f, 0.0f, 0.0f, 0.6f};
};

// A filled shape: triangles (three vertices each) in one colour.
struct HudShape {
  std::vector<glm::vec2> trianglesPixels;
  glm::vec4 rgba{1.0f, 1.0f, 1.0f, 1.0f};
};

using HudItem = std::variant<HudTextBlock, HudShape>;

struct HudVertex {
  glm::vec2 positionPixels;
  glm::vec4 rgba;
};

// The size of a block's box, padding included, in screen pixels.
glm::vec2 hudBlockSizePixels(const HudTextBlock& block);

// Triangles for the items in order: a block's box, then its glyphs (six vertices a quad); a
// shape's triangles as they are.
std::vector<HudVertex> buildHudTriangles(std::span<const HudItem> items);
std::vector<HudVertex> buildHudTriangles(std::span<const HudTextBlock> blocks);

// Needs a current GL 3.3 core context for its whole life, like TerrainRenderer.
class HudRenderer {
 public:
  // Loads <shaderDirectory>/hud.vert and hud.frag (empty: defaultShaderDirectory(), embedded).
  static Result<std::unique_ptr<HudRenderer>> create(const std::filesystem::path& shaderDirectory);
  ~HudRenderer();
  HudRenderer(const HudRenderer&) = delete;
  HudRenderer& operator=(const HudRenderer&) = delete;

  // Builds and uploads the items' triangles; draw() draws them until the next call.
  void setItems(std::span<const HudItem> items);
  // Blends the text over the current framebuffer's (0, 0, width, height) viewport, without depth
  // test; leaves depth test and culling enabled and blending disabled, as TerrainRenderer does.
  void draw(int widthPixels, int heightPixels) const;

 private:
  struct Impl;
  explicit HudRenderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace globe::render
