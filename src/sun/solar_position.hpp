// Where the Sun is: NREL's Solar Position Algorithm (I. Reda and A. Andreas, NREL/TP-560-34302,
// 2004/2008; ±0.0003° from −2000 to 6000), for an observer on the ellipsoid and as one direction
// for the whole globe (the light the terrain is drawn under).
#pragma once

#include <limits>

#include <glm/vec3.hpp>

namespace globe::sun {

// The intermediate values the algorithm's paper tabulates for its example (tests check them).
struct SpaTerms {
  double julianDay;                     // UT
  double heliocentricLongitudeDegrees;  // L, 0..360
  double heliocentricLatitudeDegrees;   // B
  double radiusAu;                      // R, Earth-Sun distance
  double nutationLongitudeDegrees;      // Δψ
  double nutationObliquityDegrees;      // Δε
  double obliquityDegrees;              // ε, true obliquity of the ecliptic
  double rightAscensionDegrees;         // α, geocentric, 0..360
  double declinationDegrees;            // δ, geocentric
  double greenwichSiderealDegrees;      // ν, apparent sidereal time at Greenwich, 0..360
};

// Observer's view of the Sun's centre: azimuth clockwise from north, 0..360; elevation above the
// horizon, topocentric (parallax included), geometric (no refraction) unless refraction is added.
struct SolarPosition {
  double azimuthDegrees;
  double elevationDegrees;
  double hourAngleDegrees;  // H, the observer's local hour angle (geocentric), 0..360
  SpaTerms terms;
};

struct Observer {
  double longitudeDegrees = 0;  // east positive
  double latitudeDegrees = 0;
  double heightMeters = 0;  // above the ellipsoid
};

// deltaT: NaN takes ΔT from delta_t.hpp for the year.
inline constexpr double kModelDeltaT = std::numeric_limits<double>::quiet_NaN();

// unixSeconds: UTC (as UT1: the difference, under a second, moves the Sun 0.004° at most).
// deltaTSeconds: TT − UT.
SolarPosition solarPosition(double unixSeconds, const Observer& observer,
                            double deltaTSeconds = kModelDeltaT);

// The atmosphere's refraction of a geometric elevation (SPA's formula, Bennett's), degrees to
// add: 0 when the Sun is further below the horizon than refraction and its radius can lift it.
double refractionDegrees(double elevationDegrees, double pressureMillibars = 1010,
                         double temperatureCelsius = 10);

// The unit vector towards the Sun from the Earth's centre, in Earth-fixed (ECEF) axes: the light
// over the whole globe (from the ground the Sun is 0.0024° away from that direction at most).
glm::dvec3 sunDirectionEcef(double unixSeconds);

}  // namespace globe::sun
