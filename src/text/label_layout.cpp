// Label decluttering: boxes against the boxes placed before them, in priority order. Quadratic
// in the number placed, which the screen bounds (a few hundred labels at most fit).
#include "text/label_layout.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/common.hpp>

namespace globe::text {
namespace {

struct LabelBox {
  glm::vec2 minPixels, maxPixels;
};

bool boxesOverlap(const LabelBox& a, const LabelBox& b) {
  return a.minPixels.x < b.maxPixels.x && b.minPixels.x < a.maxPixels.x &&
         a.minPixels.y < b.maxPixels.y && b.minPixels.y < a.maxPixels.y;
}

bool fitsAmong(const LabelBox& box, const std::vector<PlacedLabel>& placed,
               glm::ivec2 viewportPixels) {
  const LabelBox screen{{0.0f, 0.0f}, glm::vec2(viewportPixels)};
  if (!boxesOverlap(box, screen)) return false;
  const LabelBox padded{box.minPixels - kLabelMarginPixels, box.maxPixels + kLabelMarginPixels};
  return std::none_of(placed.begin(), placed.end(), [&](const PlacedLabel& other) {
    return boxesOverlap(padded, {other.minPixels, other.maxPixels});
  });
}

}  // namespace

float labelHaloPixels(float sizePixels) {
  if (!std::isfinite(sizePixels)) return 0.0f;
  return std::clamp(sizePixels * 0.125f, 1.5f, 4.0f);
}

LabelGeometry labelGeometry(const ScreenLabel& label, const TextExtent& text) {
  LabelGeometry out;
  const glm::vec2 anchor(label.anchorPixels);
  const float iconHalf = 0.5f * label.iconSizePixels;
  out.hasIcon = !label.iconKey.empty() && std::isfinite(iconHalf) && iconHalf > 0.0f;
  float textLeft = anchor.x;
  if (out.hasIcon) {
    out.iconMinPixels = anchor - iconHalf;
    out.iconMaxPixels = anchor + iconHalf;
    textLeft += iconHalf + std::max(2.0f, 0.25f * label.sizePixels);
  }
  out.hasText = text.widthPixels > 0.0f;
  if (out.hasText) {
    const float halo = std::ceil(labelHaloPixels(label.sizePixels));
    // Whole pixels: glyph bitmaps were rasterised on the pixel grid, so the text stays crisp.
    out.baselineOriginPixels = {
        std::round(textLeft + halo),
        std::round(anchor.y + 0.5f * (text.ascentPixels - text.descentPixels))};
    out.textMinPixels = {out.baselineOriginPixels.x - halo,
                         out.baselineOriginPixels.y - text.ascentPixels - halo};
    out.textMaxPixels = {out.baselineOriginPixels.x + text.widthPixels + halo,
                         out.baselineOriginPixels.y + text.descentPixels + halo};
  }
  return out;
}

std::vector<PlacedLabel> layoutLabels(std::span<const ScreenLabel> labels,
                                      glm::ivec2 viewportPixels, const MeasureText& measure) {
  std::vector<PlacedLabel> placed;
  for (size_t i = 0; i < labels.size(); ++i) {
    const ScreenLabel& label = labels[i];
    if (!std::isfinite(label.anchorPixels.x) || !std::isfinite(label.anchorPixels.y)) continue;
    const TextExtent extent =
        label.text.empty() ? TextExtent{} : measure(label.text, label.sizePixels);
    const LabelGeometry geometry = labelGeometry(label, extent);
    std::optional<LabelBox> icon, whole;
    if (geometry.hasIcon) icon = LabelBox{geometry.iconMinPixels, geometry.iconMaxPixels};
    if (geometry.hasText) {
      whole = LabelBox{geometry.textMinPixels, geometry.textMaxPixels};
      if (icon) {
        whole->minPixels = glm::min(whole->minPixels, icon->minPixels);
        whole->maxPixels = glm::max(whole->maxPixels, icon->maxPixels);
      }
    } else {
      whole = icon;
    }
    if (!whole) continue;
    if (fitsAmong(*whole, placed, viewportPixels)) {
      placed.push_back({i, whole->minPixels, whole->maxPixels, geometry.hasText});
    } else if (icon && geometry.hasText && fitsAmong(*icon, placed, viewportPixels)) {
      placed.push_back({i, icon->minPixels, icon->maxPixels, false});
    }
  }
  return placed;
}

}  // namespace globe::text
