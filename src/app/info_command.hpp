// `globe info PYRAMID [--json]`: levels, tile counts, bounds and height range of a pyramid.
#pragma once

#include <string>

#include "io/pyramid_manifest.hpp"

namespace globe::app {

std::string formatPyramidInfoText(const io::PyramidManifest& manifest, const std::string& path);
std::string formatPyramidInfoJson(const io::PyramidManifest& manifest, const std::string& path);

}  // namespace globe::app
