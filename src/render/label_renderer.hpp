// Draws placemark labels (an icon and UTF-8 text with a dark halo, decluttered) and info panels
// over the frame in window pixels (y down), with FreeType + HarfBuzz text from a glyph atlas.
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "core/result.hpp"
#include "formats/image_io.hpp"
#include "text/font_face.hpp"
#include "text/label_layout.hpp"

namespace globe::render {

// The built-in icon (makePinIcon), available without any file.
inline constexpr std::string_view kPinIconKey = "pin";

// An info panel's look: the first paragraph (a placemark's name) larger than the rest.
struct TextPanelStyle {
  float titleSizePixels = 18.0f;
  float bodySizePixels = 14.0f;
  float paddingPixels = 8.0f;
  float paragraphGapPixels = 6.0f;
  glm::vec4 textRgba{1.0f, 1.0f, 1.0f, 1.0f};
  glm::vec4 backgroundRgba{0.0f, 0.0f, 0.0f, 0.65f};
};

// Needs a current GL 3.3 core context for its whole life, like HudRenderer.
class LabelRenderer {
 public:
  // Loads <shaderDirectory>/label.vert and label.frag (empty: defaultShaderDirectory(), embedded)
  // and the font (findLabelFont()).
  static Result<std::unique_ptr<LabelRenderer>> create(
      const std::filesystem::path& shaderDirectory);
  ~LabelRenderer();
  LabelRenderer(const LabelRenderer&) = delete;
  LabelRenderer& operator=(const LabelRenderer&) = delete;

  // Uploads the image (straight alpha) as the icon `key` on the first call for that key; later
  // calls for the key, and images whose pixels do not match their size, change nothing.
  void setIcon(const std::string& key, const formats::ImageRgba& image);
  bool hasIcon(const std::string& key) const;

  // layoutLabels with this renderer's font: what draw() will draw, for picking.
  std::vector<text::PlacedLabel> layout(std::span<const text::ScreenLabel> labels,
                                  glm::ivec2 viewportPixels) const;
  // Blends the placed labels' icons (unknown keys draw none), then their text, over the current
  // framebuffer's (0, 0, width, height) viewport without depth test; leaves depth test and
  // culling enabled and blending disabled, as HudRenderer does.
  void draw(std::span<const text::ScreenLabel> labels, std::span<const text::PlacedLabel> placed,
            glm::ivec2 viewportPixels);

  // The size of the panel drawTextPanel draws (no GL).
  glm::vec2 textPanelSizePixels(const std::vector<std::string>& paragraphs,
                                float maxWidthPixels) const;
  // A translucent dark box at topLeftPixels, at most maxWidthPixels wide, holding the paragraphs
  // word-wrapped (wrapText), the first one larger; blended like draw().
  void drawTextPanel(const std::vector<std::string>& paragraphs, glm::vec2 topLeftPixels,
                     float maxWidthPixels, glm::ivec2 viewportPixels);

  const text::FontFace& font() const;

 private:
  struct Impl;
  explicit LabelRenderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace globe::render
