// Geodetic coordinates (longitude, latitude, height above the ellipsoid) and angle helpers.
#pragma once

#include <numbers>

namespace globe::geo {

// Dividing by 180 first keeps multiples of 90 degrees exact (180 -> pi, 90 -> pi/2).
constexpr double degreesToRadians(double degrees) { return degrees / 180.0 * std::numbers::pi; }
constexpr double radiansToDegrees(double radians) { return radians / std::numbers::pi * 180.0; }

// Maps any finite longitude into [-pi, pi]. Values already in [-pi, pi] are returned unchanged
// (so +pi stays +pi and -pi stays -pi); non-finite values are returned as they are.
double wrapLongitudeRadians(double longitudeRadians);

struct Cartographic {
  double longitudeRadians;  // positive east of Greenwich
  double latitudeRadians;   // geodetic latitude, positive north
  double heightMeters;      // along the ellipsoid normal, above the ellipsoid

  static Cartographic fromDegrees(double longitudeDegrees, double latitudeDegrees,
                                  double heightMeters = 0) {
    return {degreesToRadians(longitudeDegrees), degreesToRadians(latitudeDegrees), heightMeters};
  }
  double longitudeDegrees() const { return radiansToDegrees(longitudeRadians); }
  double latitudeDegrees() const { return radiansToDegrees(latitudeRadians); }
};

}  // namespace globe::geo
