// A source's vertical units as JSON: the manifest's `sources[].verticalUnits` and `globe info
// --json` write the same keys through this one function.
#pragma once

#include <nlohmann/json.hpp>

#include "formats/vertical_units.hpp"

namespace globe::formats {

nlohmann::json verticalUnitsToJson(const VerticalUnits& units);

}  // namespace globe::formats
