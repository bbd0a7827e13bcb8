#include "apps/globe/layer_argument.hpp"

#include <cmath>
#include <cstdlib>

#include "services/imagery_services.hpp"

namespace globe::app {

Result<scene::LayerOptions> parseLayerArgument(const std::string& text) {
  scene::LayerOptions layer;
  size_t comma = text.rfind(',');
  std::string directory = text;
  if (comma != std::string::npos && services::isImageryService(text)) {
    char* end = nullptr;
    const std::string tail = text.substr(comma + 1);
    const double value = std::strtod(tail.c_str(), &end);
    if (tail.empty() || end != tail.c_str() + tail.size() || !(value >= 0 && value <= 1)) {
      comma = std::string::npos;
    }
  }
  if (comma != std::string::npos) {
    const std::string opacity = text.substr(comma + 1);
    char* end = nullptr;
    const double value = std::strtod(opacity.c_str(), &end);
    if (opacity.empty() || end != opacity.c_str() + opacity.size() || !std::isfinite(value) ||
        value < 0 || value > 1) {
      return makeError("--layer " + text + ": the opacity after the comma must be 0..1, not '" +
                       opacity + "'");
    }
    layer.opacity = static_cast<float>(value);
    directory = text.substr(0, comma);
  }
  if (directory.empty()) return makeError("--layer " + text + ": no layer directory");
  layer.directory = directory;
  return layer;
}

}  // namespace globe::app
