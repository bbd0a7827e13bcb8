// KML colours: "aabbggrr" hexadecimal (alpha first, then blue, green, red).
#pragma once

#include <optional>
#include <string_view>

#include "overlays/overlay_model.hpp"

namespace globe::overlays {

// Parses aabbggrr (surrounding whitespace and a leading '#' tolerated; six digits "bbggrr" read
// as opaque). nullopt for anything else: the caller keeps the default colour, as Google Earth.
std::optional<Rgba> parseKmlColor(std::string_view text);

}  // namespace globe::overlays
