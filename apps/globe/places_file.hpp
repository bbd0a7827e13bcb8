// Where `globe` finds its gazetteer: $GLOBE_PLACES, else the installed share/globe/places.tsv.gz
// beside the program, else the source tree's data/places/places.tsv.gz (a build tree).
#pragma once

#include <filesystem>

#include "core/result.hpp"
#include "places/gazetteer.hpp"

namespace globe::app {

std::filesystem::path defaultPlacesFile();
// The gazetteer of `file` (defaultPlacesFile() when empty), read once per process and kept.
Result<const places::Gazetteer*> loadPlaces(const std::filesystem::path& file = {});

}  // namespace globe::app
