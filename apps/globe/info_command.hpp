// `globe info DIR [--json]`: levels, tile counts, bounds and height range of a pyramid, or levels,
// tile counts, bounds and sources of an imagery layer.
#pragma once

#include <memory>
#include <string>

#include "core/result.hpp"
#include "formats/layer_manifest.hpp"
#include "formats/pyramid_manifest.hpp"
#include "transport/network_settings.hpp"

namespace globe::app {

struct InfoOptions {
  std::string location;  // a pyramid or an imagery layer: a directory or its http(s) URL
  bool json = false;     // machine-readable (a layer: its manifest as JSON)
  std::shared_ptr<transport::Network> network;  // for a URL
};

// The text `globe info` prints: the pyramid's manifest, else the imagery layer's; errors name
// what is missing or wrong.
Result<std::string> runInfo(const InfoOptions& options);

std::string formatPyramidInfoText(const formats::PyramidManifest& manifest,
                                  const std::string& path);
std::string formatPyramidInfoJson(const formats::PyramidManifest& manifest,
                                  const std::string& path);

// `globe info LAYER`: an imagery layer's levels, tile counts, bounds and sources.
std::string formatLayerInfoText(const formats::LayerManifest& manifest, const std::string& path);

}  // namespace globe::app
