// A source's vertical units as JSON: the manifest's `sources[].verticalUnits` and `globe info
// --json` write the same keys through this one function.
#pragma once

#include <nlohmann/json.hpp>

#include "io/vertical_units.hpp"

namespace globe::io {

nlohmann::json verticalUnitsToJson(const VerticalUnits& units);

}  // namespace globe::io
