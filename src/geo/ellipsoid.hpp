// The reference surface of the globe: the WGS84 ellipsoid or the paper's sphere.
// Heights in every other geo type are measured from this surface along its normal.
#pragma once

#include <optional>
#include <string_view>

namespace globe::geo {

enum class GlobeModel { Wgs84, Sphere };

// An ellipsoid of revolution about the z (polar) axis.
struct Ellipsoid {
  double semiMajorAxisMeters;  // equatorial radius a
  double semiMinorAxisMeters;  // polar radius b

  // a = 6378137 m, flattening f = 1/298.257223563, b = a(1 - f).
  static constexpr Ellipsoid wgs84() {
    constexpr double a = 6378137.0;
    constexpr double f = 1.0 / 298.257223563;
    return Ellipsoid{a, a * (1.0 - f)};
  }
  // The paper's sphere; 6371 km is the mean earth radius.
  static constexpr Ellipsoid sphere(double radiusMeters = 6371000.0) {
    return Ellipsoid{radiusMeters, radiusMeters};
  }

  constexpr bool isSphere() const { return semiMajorAxisMeters == semiMinorAxisMeters; }
  // First eccentricity squared, e^2 = 1 - b^2/a^2 (0 for a sphere).
  constexpr double eccentricitySquared() const {
    const double ratio = semiMinorAxisMeters / semiMajorAxisMeters;
    return 1.0 - ratio * ratio;
  }
};

Ellipsoid ellipsoidFor(GlobeModel model);
// Accepts "wgs84" or "sphere" (ASCII case-insensitive); nullopt for anything else.
std::optional<GlobeModel> parseGlobeModel(std::string_view text);
// "wgs84" or "sphere": the spelling parseGlobeModel accepts.
std::string_view toString(GlobeModel model);

}  // namespace globe::geo
