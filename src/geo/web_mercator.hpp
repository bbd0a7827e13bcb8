// Web Mercator (EPSG:3857) XYZ tile geometry, for the exporters that write 256×256 tiles for web
// maps and the services that read them: rows from the north, latitudes clamped to ±85.0511°.
#pragma once

#include <cstdint>

namespace globe::geo {

inline constexpr uint32_t kWebMercatorTileSizePixels = 256;
inline constexpr double kWebMercatorMaxLatitudeDegrees = 85.05112877980659;
// Half the square world's side: the sphere's equatorial circumference / 2.
inline constexpr double kWebMercatorHalfWorldMeters = 20037508.342789244;

// The tile row (fractional, from the north) of a latitude at `zoom`, latitude clamped.
double webMercatorRowOf(double latitudeDegrees, uint32_t zoom);
// The latitude of a fractional row at `zoom`.
double webMercatorLatitudeRadiansOfRow(double row, uint32_t zoom);
// The longitude of a fractional column at `zoom`.
double webMercatorLongitudeDegreesOfColumn(double column, uint32_t zoom);

// The XYZ tiles (rows from the north) a region covers at `zoom`, inclusive.
struct WebMercatorTileRange {
  uint32_t firstX = 0, lastX = 0, firstY = 0, lastY = 0;
  uint64_t count() const { return uint64_t{lastX - firstX + 1} * (lastY - firstY + 1); }
};
WebMercatorTileRange webMercatorTilesOf(double westDegrees, double southDegrees, double eastDegrees,
                                        double northDegrees, uint32_t zoom);

// Metres per pixel of a 256-pixel tile at `zoom` on the projection's plane (TMS units-per-pixel).
double webMercatorMetersPerPixel(uint32_t zoom);
// A longitude or latitude (clamped) as projected metres.
double webMercatorXMeters(double longitudeDegrees);
double webMercatorYMeters(double latitudeDegrees);

}  // namespace globe::geo
