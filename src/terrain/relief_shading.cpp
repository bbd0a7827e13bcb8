// The hill-shading weight on draped imagery, from the imagery texel over the terrain sample.
#include "terrain/relief_shading.hpp"

#include <algorithm>
#include <cmath>

namespace globe::terrain {

std::optional<ImageryLighting> parseImageryLighting(std::string_view text) {
  if (text == "auto") return ImageryLighting::Auto;
  if (text == "on") return ImageryLighting::On;
  if (text == "off") return ImageryLighting::Off;
  return std::nullopt;
}

std::string_view toString(ImageryLighting lighting) {
  switch (lighting) {
    case ImageryLighting::Off:
      return "off";
    case ImageryLighting::On:
      return "on";
    case ImageryLighting::Auto:
      break;
  }
  return "auto";
}

ImageryLighting nextImageryLighting(ImageryLighting lighting) {
  switch (lighting) {
    case ImageryLighting::Auto:
      return ImageryLighting::On;
    case ImageryLighting::On:
      return ImageryLighting::Off;
    case ImageryLighting::Off:
      break;
  }
  return ImageryLighting::Auto;
}

double reliefShadingWeight(double imageryTexelMeters, double terrainSpacingMeters) {
  const double ratio = imageryTexelMeters / terrainSpacingMeters;
  if (!std::isfinite(ratio) || !(ratio > 0.0)) return 1.0;
  const double along = std::log(ratio / kGentleReliefTexelRatio) /
                       std::log(kFullReliefTexelRatio / kGentleReliefTexelRatio);
  return kGentleReliefWeight + (1.0 - kGentleReliefWeight) * std::clamp(along, 0.0, 1.0);
}

double levelGroundLightWeight(ImageryLighting lighting) {
  switch (lighting) {
    case ImageryLighting::Off:
      return 0.0;
    case ImageryLighting::On:
      return 1.0;
    case ImageryLighting::Auto:
      break;
  }
  return kGentleReliefWeight;
}

double imageryLightWeight(ImageryLighting lighting, double imageryTexelMeters,
                          double terrainSpacingMeters) {
  if (lighting == ImageryLighting::Auto) {
    return reliefShadingWeight(imageryTexelMeters, terrainSpacingMeters);
  }
  return levelGroundLightWeight(lighting);  // Off 0, On 1
}

}  // namespace globe::terrain
