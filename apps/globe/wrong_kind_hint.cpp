#include "apps/globe/wrong_kind_hint.hpp"

#include <algorithm>
#include <array>
#include <string_view>

#include "core/ascii_case.hpp"

namespace globe::app {

std::string layerGivenAnOverlayHint(const std::filesystem::path& layerPath) {
  static constexpr std::array<std::string_view, 5> kOverlayExtensions = {
      ".kml", ".kmz", ".gpx", ".geojson", ".json"};
  const std::string extension = core::asciiLower(layerPath.extension().string());
  std::error_code error;
  if (!std::filesystem::is_regular_file(layerPath, error) ||
      std::find(kOverlayExtensions.begin(), kOverlayExtensions.end(), extension) ==
          kOverlayExtensions.end()) {
    return "";
  }
  return " (" + layerPath.string() + " is an overlay file: give it with --overlay)";
}

std::string overlayGivenALayerHint(const std::filesystem::path& overlayPath) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(overlayPath / "layer.json", error)) return "";
  return " (" + overlayPath.string() + " is a layer folder: give it with --layer)";
}

}  // namespace globe::app
