// A source's conditioning counts as JSON: the manifest's `sources[].conditioning` and
// `globe info --json` write the same keys through this one function.
#pragma once

#include <nlohmann/json.hpp>

#include "formats/pyramid_manifest.hpp"

namespace globe::formats {

nlohmann::json conditioningToJson(const SourceConditioning& conditioning);

}  // namespace globe::formats
