// Who the data on screen is from, as the services ask it to be shown: a small block at the
// bottom right of the window's HUD and of every snapshot (unless --no-attribution).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/hud_renderer.hpp"

namespace globe::app {

// The attributions as HUD lines in the HUD font's ASCII ("©" as "(c)"), at the bottom right of a
// width × height frame; nullopt when there are none.
std::optional<render::HudTextBlock> attributionBlock(const std::vector<std::string>& attributions,
                                                     int widthPixels, int heightPixels);

}  // namespace globe::app
