#include "terrain/height_block.hpp"

#include <algorithm>
#include <cmath>

#include "terrain/tin_tile.hpp"

namespace globe::terrain {

bool isValidBlockSize(uint32_t verticesPerSide) {
  if (verticesPerSide < 3 || verticesPerSide > 1025) return false;
  const uint32_t cells = verticesPerSide - 1;
  return (cells & (cells - 1)) == 0;
}

void HeightRange::include(const HeightRange& other) {
  minimumMeters = std::min(minimumMeters, other.minimumMeters);
  maximumMeters = std::max(maximumMeters, other.maximumMeters);
}

HeightRange surfaceHeightRange(const HeightBlock& block) {
  HeightRange range{INT16_MAX, INT16_MIN};
  for (int16_t sample : block.heights) {
    const auto low = static_cast<int16_t>(surfaceHeightMeters(sample, SeaSurface::SeaFloor));
    const auto high = static_cast<int16_t>(surfaceHeightMeters(sample, SeaSurface::Water));
    range.minimumMeters = std::min(range.minimumMeters, low);
    range.maximumMeters = std::max(range.maximumMeters, high);
  }
  // An upsampled block's exact heights lie between its rounded samples': widened to whole metres.
  for (double meters : block.exactSurfaceMeters) {
    range.minimumMeters = std::min(range.minimumMeters, static_cast<int16_t>(std::floor(meters)));
    range.maximumMeters = std::max(range.maximumMeters, static_cast<int16_t>(std::ceil(meters)));
  }
  if (block.tin) {  // the drawn surface: its vertices, widened to whole metres
    auto clamp16 = [](double m) {
      return static_cast<int16_t>(std::clamp(m, double{INT16_MIN}, double{INT16_MAX}));
    };
    range.minimumMeters =
        std::min(range.minimumMeters, clamp16(std::floor(block.tin->minimumHeightMeters())));
    range.maximumMeters =
        std::max(range.maximumMeters, clamp16(std::ceil(block.tin->maximumHeightMeters())));
  }
  if (block.heights.empty()) range = HeightRange{};
  return range;
}

}  // namespace globe::terrain
