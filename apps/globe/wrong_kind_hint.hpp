// A hint for a file given to the wrong option: an overlay file to --layer, a layer folder to
// --overlay. The options' own errors say what failed; this says what was probably meant.
#pragma once

#include <filesystem>
#include <string>

namespace globe::app {

// " (PATH is an overlay file: give it with --overlay)" when `layerPath` is a regular file
// named .kml, .kmz, .gpx, .geojson or .json; "" otherwise.
std::string layerGivenAnOverlayHint(const std::filesystem::path& layerPath);

// " (PATH is a layer folder: give it with --layer)" when `overlayPath` is a folder holding a
// layer.json; "" otherwise.
std::string overlayGivenALayerHint(const std::filesystem::path& overlayPath);

}  // namespace globe::app
