#include "conditioning/vertex_sample.hpp"

#include <algorithm>
#include <cmath>

#include "terrain/height_block.hpp"

namespace globe::conditioning {
int16_t landSample(double heightMeters) {
  const auto rounded = static_cast<int16_t>(
      std::clamp(std::lround(heightMeters), static_cast<long>(terrain::kLowestLandMeters), 32767L));
  // -9999 is water: a land height that rounds to it moves a metre deeper.
  return rounded == terrain::kNoDataHeight ? static_cast<int16_t>(-10000) : rounded;
}

int16_t interpolateSample(const std::array<int16_t, 4>& samples, double tu, double tv) {
  auto bilinear = [&](terrain::SeaSurface sea) {
    auto h = [&](size_t k) { return terrain::surfaceHeightMeters(samples[k], sea); };
    return (1 - tv) * ((1 - tu) * h(0) + tu * h(1)) + tv * ((1 - tu) * h(2) + tu * h(3));
  };
  bool anyWater = false, allWater = true, measuredFloor = false;
  for (int16_t s : samples) {
    const bool water = terrain::isWater(s);
    anyWater = anyWater || water;
    allWater = allWater && water;
    measuredFloor = measuredFloor || (water && s != terrain::kNoDataHeight);
  }
  if (!anyWater) return landSample(bilinear(terrain::SeaSurface::Water));
  const double floorOrLand = bilinear(terrain::SeaSurface::SeaFloor);
  if (allWater) return terrain::encodeWater(std::min(floorOrLand, 0.0));
  if (measuredFloor) {
    return floorOrLand < 0.0 ? terrain::encodeWater(floorOrLand) : landSample(floorOrLand);
  }
  const int16_t nearest =
      tv < 0.5 ? (tu < 0.5 ? samples[0] : samples[1]) : (tu < 0.5 ? samples[2] : samples[3]);
  if (terrain::isWater(nearest)) return terrain::kNoDataHeight;
  return landSample(bilinear(terrain::SeaSurface::Water));
}

}  // namespace globe::conditioning
