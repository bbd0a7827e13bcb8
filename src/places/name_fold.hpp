// Names compared as people type them: lower-case ASCII letters and digits, accents dropped
// ("Zürich" as "zurich", "São Paulo" as "sao paulo", "Łódź" as "lodz"), anything else a single
// space. The gazetteer's keys were folded so (tools/places/build_places.py).
#pragma once

#include <string>
#include <string_view>

namespace globe::places {

std::string foldName(std::string_view utf8);

}  // namespace globe::places
