// `globe info DIR [--json]`: levels, tile counts, bounds and height range of a pyramid, or levels,
// tile counts, bounds and sources of an imagery layer.
#pragma once

#include <string>

#include "formats/layer_manifest.hpp"
#include "formats/pyramid_manifest.hpp"

namespace globe::app {

std::string formatPyramidInfoText(const formats::PyramidManifest& manifest,
                                  const std::string& path);
std::string formatPyramidInfoJson(const formats::PyramidManifest& manifest,
                                  const std::string& path);

// `globe info LAYER`: an imagery layer's levels, tile counts, bounds and sources.
std::string formatLayerInfoText(const formats::LayerManifest& manifest, const std::string& path);

}  // namespace globe::app
