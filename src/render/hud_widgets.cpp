// Compass rose and scale bar geometry.
#include "render/hud_widgets.hpp"

#include <cmath>
#include <numbers>

namespace globe::render {
namespace {

constexpr glm::vec4 kDark{0.0f, 0.0f, 0.0f, 0.55f};
constexpr glm::vec4 kLight{0.92f, 0.94f, 0.96f, 1.0f};
constexpr glm::vec4 kNorth{0.9f, 0.15f, 0.1f, 1.0f};

void triangle(HudShape& shape, glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  shape.trianglesPixels.insert(shape.trianglesPixels.end(), {a, b, c});
}

void rectangle(HudShape& shape, glm::vec2 topLeft, glm::vec2 bottomRight) {
  const glm::vec2 topRight(bottomRight.x, topLeft.y), bottomLeft(topLeft.x, bottomRight.y);
  triangle(shape, topLeft, topRight, bottomRight);
  triangle(shape, topLeft, bottomRight, bottomLeft);
}

// One line of text with no box, its centre at centrePixels (stb_easy_font's glyphs are about
// 5 x 7 font pixels a character, 6 apart).
HudTextBlock centredText(const std::string& text, glm::vec2 centrePixels, float scale,
                         const glm::vec4& rgba) {
  HudTextBlock block;
  block.lines = {text};
  block.scale = scale;
  block.paddingPixels = 0;
  block.textRgba = rgba;
  block.backgroundRgba = glm::vec4(0.0f);
  const glm::vec2 size(static_cast<float>(6 * text.size() - 1) * scale, 7.0f * scale);
  block.topLeftPixels = centrePixels - 0.5f * size;
  return block;
}

}  // namespace

std::vector<HudItem> compassRose(glm::vec2 centrePixels, float radiusPixels, float textScale,
                                 double northClockwiseFromUpRadians) {
  const double angle = std::isfinite(northClockwiseFromUpRadians) ? northClockwiseFromUpRadians : 0;
  // Screen directions (y down) of north and of its right-hand perpendicular (east).
  const glm::vec2 north(static_cast<float>(std::sin(angle)), static_cast<float>(-std::cos(angle)));
  const glm::vec2 east(-north.y, north.x);
  const float r = radiusPixels;
  const glm::vec2 c = centrePixels;

  HudShape disc{{}, kDark};
  constexpr int kSides = 40;
  for (int i = 0; i < kSides; ++i) {
    const double a0 = 2 * std::numbers::pi * i / kSides,
                 a1 = 2 * std::numbers::pi * (i + 1) / kSides;
    triangle(disc, c, c + r * glm::vec2(std::cos(a0), std::sin(a0)),
             c + r * glm::vec2(std::cos(a1), std::sin(a1)));
  }
  HudShape ticks{{}, kLight};
  for (const glm::vec2 toward : {east, -north, -east}) {
    const glm::vec2 side = 0.06f * r * glm::vec2(-toward.y, toward.x);
    const glm::vec2 outer = c + 0.95f * r * toward, inner = c + 0.72f * r * toward;
    triangle(ticks, outer + side, outer - side, inner);
  }
  const float half = 0.17f * r;  // half the needles' width at the centre
  HudShape south{{}, kLight};
  triangle(south, c + half * east, c - 0.6f * r * north, c - half * east);
  HudShape northNeedle{{}, kNorth};
  triangle(northNeedle, c - half * east, c + 0.6f * r * north, c + half * east);
  return {disc, ticks, south, northNeedle,
          centredText("N", c + 0.8f * r * north, textScale, kLight)};
}

std::vector<HudItem> scaleBar(glm::vec2 leftEndPixels, float lengthPixels, const std::string& label,
                              float textScale) {
  const float thick = 2.0f * textScale, tick = 5.0f * textScale, edge = std::max(1.0f, textScale);
  const glm::vec2 p = leftEndPixels;
  const float length = std::isfinite(lengthPixels) ? std::max(lengthPixels, 0.0f) : 0.0f;
  HudShape outline{{}, kDark};
  rectangle(outline, p + glm::vec2(-edge, -thick - edge), p + glm::vec2(length + edge, edge));
  rectangle(outline, p + glm::vec2(-edge, -tick - edge), p + glm::vec2(thick + edge, edge));
  rectangle(outline, p + glm::vec2(length - thick - edge, -tick - edge),
            p + glm::vec2(length + edge, edge));
  HudShape bar{{}, kLight};
  rectangle(bar, p + glm::vec2(0, -thick), p + glm::vec2(length, 0));
  rectangle(bar, p + glm::vec2(0, -tick), p + glm::vec2(thick, 0));
  rectangle(bar, p + glm::vec2(length - thick, -tick), p + glm::vec2(length, 0));
  HudTextBlock text =
      centredText(label, p + glm::vec2(0.5f * length, -tick - 8.0f * textScale), textScale, kLight);
  text.backgroundRgba = kDark;
  text.paddingPixels = 2.0f * textScale;
  text.topLeftPixels -= glm::vec2(text.paddingPixels);
  return {outline, bar, text};
}

}  // namespace globe::render
