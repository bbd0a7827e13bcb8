// Where labels go on the screen and which are drawn: greedy decluttering in priority order, on
// the CPU from text measurements alone (no GL), so it is unit-testable and the renderer and
// picking agree on every box.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "text/font_face.hpp"

namespace globe::text {

struct ScreenLabel {
  std::string text;           // UTF-8
  glm::dvec2 anchorPixels{};  // window pixels, y down from the top-left
  float sizePixels = 16.0f;   // font size
  glm::vec4 textRgba{1, 1, 1, 1};
  glm::vec4 haloRgba{0, 0, 0, 0.8f};
  // An icon at the anchor (centred on it), drawn before the text; the text goes right of it.
  std::string iconKey;  // empty: no icon
  float iconSizePixels = 0;
  glm::vec4 iconRgba{1, 1, 1, 1};  // multiplies the icon's colours (KML IconStyle color)
};

// What was drawn, for picking: the label's box (icon and text, halo included) in window pixels.
struct PlacedLabel {
  size_t index;  // into the labels given to layout()
  glm::vec2 minPixels, maxPixels;
  bool withText = true;  // false: only the icon fitted, the text is not drawn
};

// How wide and tall a label's text is (FontFace::measure, or a stand-in in tests).
using MeasureText = std::function<TextExtent(const std::string& utf8, float sizePixels)>;

// The halo's radius around glyphs at a font size (the glyph atlas renders it, layout reserves it).
float labelHaloPixels(float sizePixels);

// Clear space kept between placed labels' boxes.
inline constexpr float kLabelMarginPixels = 2.0f;

// One label's parts in window pixels. The text is vertically centred on the anchor, starting at
// the anchor without an icon, right of the icon with one.
struct LabelGeometry {
  bool hasIcon = false;
  glm::vec2 iconMinPixels{}, iconMaxPixels{};
  bool hasText = false;
  glm::vec2 baselineOriginPixels{};            // the text's left end on its baseline, whole pixels
  glm::vec2 textMinPixels{}, textMaxPixels{};  // the line box grown by the halo
};
LabelGeometry labelGeometry(const ScreenLabel& label, const TextExtent& text);

// Greedy in order: a label whose box (plus kLabelMarginPixels) overlaps an already placed box, or
// lies wholly outside the viewport, is dropped, unless its icon alone fits: then the icon is kept
// without its text. Labels with a non-finite anchor, or with neither text nor icon, are dropped.
std::vector<PlacedLabel> layoutLabels(std::span<const ScreenLabel> labels,
                                      glm::ivec2 viewportPixels, const MeasureText& measure);

}  // namespace globe::text
