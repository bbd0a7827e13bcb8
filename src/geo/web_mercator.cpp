#include "geo/web_mercator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace globe::geo {

double webMercatorRowOf(double latitudeDegrees, uint32_t zoom) {
  const double lat =
      std::clamp(latitudeDegrees, -kWebMercatorMaxLatitudeDegrees, kWebMercatorMaxLatitudeDegrees) *
      std::numbers::pi / 180;
  return (1 - std::log(std::tan(lat) + 1 / std::cos(lat)) / std::numbers::pi) / 2 *
         std::ldexp(1.0, static_cast<int>(zoom));
}

double webMercatorLatitudeRadiansOfRow(double row, uint32_t zoom) {
  const double n = std::numbers::pi * (1 - 2 * row / std::ldexp(1.0, static_cast<int>(zoom)));
  return std::atan(std::sinh(n));
}

double webMercatorLongitudeDegreesOfColumn(double column, uint32_t zoom) {
  return column / std::ldexp(1.0, static_cast<int>(zoom)) * 360 - 180;
}

WebMercatorTileRange webMercatorTilesOf(double westDegrees, double southDegrees, double eastDegrees,
                                        double northDegrees, uint32_t zoom) {
  const double tiles = std::ldexp(1.0, static_cast<int>(zoom));
  const auto clampIndex = [&](double v) {
    return static_cast<uint32_t>(std::clamp(std::floor(v), 0.0, tiles - 1));
  };
  return {clampIndex((westDegrees + 180) / 360 * tiles),
          clampIndex((eastDegrees + 180) / 360 * tiles),
          clampIndex(webMercatorRowOf(northDegrees, zoom)),
          clampIndex(webMercatorRowOf(southDegrees, zoom))};
}

double webMercatorMetersPerPixel(uint32_t zoom) {
  return 2 * kWebMercatorHalfWorldMeters / kWebMercatorTileSizePixels /
         std::ldexp(1.0, static_cast<int>(zoom));
}

double webMercatorXMeters(double longitudeDegrees) {
  return longitudeDegrees / 180 * kWebMercatorHalfWorldMeters;
}

double webMercatorYMeters(double latitudeDegrees) {
  // Row 0.5 of zoom 0 is the equator; rows grow southwards.
  return (1 - 2 * webMercatorRowOf(latitudeDegrees, 0)) * kWebMercatorHalfWorldMeters;
}

}  // namespace globe::geo
