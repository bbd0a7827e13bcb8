#include "terrain/water_mask_weight.hpp"

#include <algorithm>
#include <cmath>

namespace globe::terrain {

double waterMaskWeight(double maskTexelDegrees, double terrainStepDegrees) {
  const double ratio = terrainStepDegrees / maskTexelDegrees;
  if (!(maskTexelDegrees > 0) || !(terrainStepDegrees > 0) || !std::isfinite(ratio)) return 1.0;
  return std::clamp(
      (ratio - kTerrainDecidesStepRatio) / (kMaskDecidesStepRatio - kTerrainDecidesStepRatio), 0.0,
      1.0);
}

}  // namespace globe::terrain
