// Names compared as people type them: lower-case ASCII letters and digits, accents dropped
// ("Zürich" as "zurich", "São Paulo" as "sao paulo", "Łódź" as "lodz"), anything else a single
// space. The gazetteer's keys were folded so (tools/places/build_places.py).
#pragma once

#include <string>
#include <string_view>

namespace globe::places {

std::string foldName(std::string_view utf8);
// A name for a display that draws ASCII only (the window's HUD): ASCII kept as it is, Latin
// letters with accents as their base letters ("Zürich" as "Zurich", "Ålesund" as "Alesund"),
// anything else '?'.
std::string asciiForDisplay(std::string_view utf8);

}  // namespace globe::places
