// KML's <coordinates> and gx:Track's <gx:coord> text as positions.
#pragma once

#include <string_view>
#include <vector>

#include "core/result.hpp"
#include "overlays/overlay_model.hpp"

namespace globe::overlays {

// "lon,lat[,alt] lon,lat[,alt] ...": tuples separated by any whitespace (newlines, tabs), the
// components by commas (spaces around the commas tolerated, as Google Earth does). Each position
// is checked (positions.hpp). Errors say which tuple and what is wrong, without the file name.
Result<std::vector<Position>> parseKmlCoordinates(std::string_view text);

// gx:coord's "lon lat [alt]", separated by whitespace.
Result<Position> parseGxCoord(std::string_view text);

}  // namespace globe::overlays
