// The HUD's drawn instruments, as flat shapes and text in window pixels (y down): a compass rose
// and a scale bar. Pure geometry: HudRenderer draws them.
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "render/hud_renderer.hpp"

namespace globe::render {

// A disc with a red needle toward north and a light one toward south, an "N" at the north end and
// ticks toward east, south and west. northClockwiseFromUpRadians: where north is on the screen
// (0: up; a camera heading h puts it at -h). textScale as HudTextBlock::scale.
std::vector<HudItem> compassRose(glm::vec2 centrePixels, float radiusPixels, float textScale,
                                 double northClockwiseFromUpRadians);

// A bar lengthPixels long whose left end is at leftEndPixels (its baseline), white on a dark
// outline, with end ticks and its label above it.
std::vector<HudItem> scaleBar(glm::vec2 leftEndPixels, float lengthPixels, const std::string& label,
                              float textScale);

}  // namespace globe::render
