// Parses --layer's "DIR" or "DIR,OPACITY" (a layer directory, URL or service, and an opacity
// 0..1): the command line's text turned into the scene's LayerOptions here, in the program.
#pragma once

#include <string>

#include "core/result.hpp"
#include "scene/imagery_layers.hpp"

namespace globe::app {

// A service's URL may hold commas (bounds=W,S,E,N): there only a number 0..1 after the last
// comma is an opacity (a URL that itself ends in ",0.5" is given as "URL,0.5,1"). Errors name
// the argument.
Result<scene::LayerOptions> parseLayerArgument(const std::string& text);

}  // namespace globe::app
