// Exposure and photo-bounded light for draped imagery (the reference of terrain.frag's drape).
#include "terrain/imagery_exposure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace globe::terrain {

double medianOpaqueLuminance(std::span<const uint8_t> rgba) {
  // A histogram rather than a sort: a level-0 tile is 64k texels, and lumas fall in 256 bins.
  std::array<uint64_t, 256> bins{};
  uint64_t count = 0;
  for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
    if (rgba[i + 3] != 255) continue;
    const double luma = 0.2126 * rgba[i] + 0.7152 * rgba[i + 1] + 0.0722 * rgba[i + 2];
    ++bins[static_cast<size_t>(std::clamp(std::lround(luma), 0L, 255L))];
    ++count;
  }
  if (count == 0) return std::numeric_limits<double>::quiet_NaN();
  uint64_t seen = 0;
  for (size_t bin = 0; bin < bins.size(); ++bin) {
    seen += bins[bin];
    if (2 * seen >= count) return static_cast<double>(bin) / 255.0;
  }
  return 1.0;
}

double exposureForMedianLuminance(double median) {
  if (!(median >= 0.0) || median >= kReadableMedianLuminance) return 1.0;
  // 1 − (1 − m)^k = t  ⇒  k = log(1 − t) / log(1 − m); m = 0 would need k = ∞.
  if (median <= 0.0) return kMaximumExposure;
  const double exposure = std::log(1.0 - kReadableMedianLuminance) / std::log(1.0 - median);
  return std::clamp(exposure, 1.0, kMaximumExposure);
}

double exposedValue(double value, double exposure) {
  return 1.0 - std::pow(1.0 - std::clamp(value, 0.0, 1.0), exposure);
}

double reliefLightMultiplier(double relief, double levelLight) {
  if (!(relief > 1.0)) return relief > 0.0 ? relief : 0.0;  // NaN: dark, not NaN
  const double headroom = 1.0 / std::max(levelLight, 1e-3) - 1.0;  // up to the photo's own
  if (headroom <= 0.0) return 1.0;
  // Slope 1 at relief 1 (no kink), then saturating: 1 + H (1 − e^(−(r − 1)/H)) < 1 + H.
  return 1.0 + headroom * (1.0 - std::exp(-(relief - 1.0) / headroom));
}

}  // namespace globe::terrain
