// The steps of the SPA paper (section 3), in its order and with its symbols.
#include "sun/solar_position.hpp"

#include <cmath>
#include <numbers>

#include "sun/delta_t.hpp"
#include "sun/spa_terms.hpp"
#include "sun/utc_time.hpp"

namespace globe::sun {
namespace {

constexpr double kDegree = std::numbers::pi / 180;
constexpr double kJ2000 = 2451545.0;

double sinDeg(double d) { return std::sin(d * kDegree); }
double cosDeg(double d) { return std::cos(d * kDegree); }
double to360(double degrees) {
  const double r = std::fmod(degrees, 360.0);
  return r < 0 ? r + 360.0 : r;
}

// Σi (Σ A·cos(B + C·JME))·JME^i over the rows of one quantity (3.2), in 1e-8 radians.
double seriesSum(const std::span<const spa::PeriodicTerm>* rows, size_t count, double jme) {
  double sum = 0;
  for (size_t i = count; i-- > 0;) {
    double row = 0;
    for (const spa::PeriodicTerm& t : rows[i]) row += t.a * std::cos(t.b + t.c * jme);
    sum = sum * jme + row;
  }
  return sum / 1e8;
}

struct Nutation {
  double longitudeDegrees, obliquityDegrees;
};

// 3.4: the five mean elements (degrees) and the 63 terms.
Nutation nutation(double jce) {
  const double x[5] = {
      297.85036 + jce * (445267.111480 + jce * (-0.0019142 + jce / 189474)),
      357.52772 + jce * (35999.050340 + jce * (-0.0001603 - jce / 300000)),
      134.96298 + jce * (477198.867398 + jce * (0.0086972 + jce / 56250)),
      93.27191 + jce * (483202.017538 + jce * (-0.0036825 + jce / 327270)),
      125.04452 + jce * (-1934.136261 + jce * (0.0020708 + jce / 450000)),
  };
  double psi = 0, epsilon = 0;
  for (const spa::NutationTerm& t : spa::kNutationTerms) {
    double argument = 0;
    for (int j = 0; j < 5; ++j) argument += x[j] * t.y[j];
    psi += (t.a + t.b * jce) * sinDeg(argument);
    epsilon += (t.c + t.d * jce) * cosDeg(argument);
  }
  return {psi / 36000000, epsilon / 36000000};
}

// 3.5: the mean obliquity of the ecliptic, arc seconds, U in units of 10,000 years.
double meanObliquityArcSeconds(double jme) {
  static constexpr double c[] = {84381.448, -4680.93, -1.55, 1999.25, -51.38, -249.67,
                                 -39.05,    7.12,     27.87, 5.79,    2.45};
  const double u = jme / 10;
  double sum = 0;
  for (size_t i = std::size(c); i-- > 0;) sum = sum * u + c[i];
  return sum;
}

// Steps 3.1-3.9: everything that does not depend on the observer.
SpaTerms geocentric(double unixSeconds, double deltaT) {
  SpaTerms s{};
  s.julianDay = unixSeconds / 86400 + 2440587.5;
  const double jde = s.julianDay + deltaT / 86400;
  const double jc = (s.julianDay - kJ2000) / 36525, jce = (jde - kJ2000) / 36525, jme = jce / 10;
  s.heliocentricLongitudeDegrees = to360(seriesSum(spa::kLongitudeTerms, 6, jme) / kDegree);
  s.heliocentricLatitudeDegrees = seriesSum(spa::kLatitudeTerms, 2, jme) / kDegree;
  s.radiusAu = seriesSum(spa::kRadiusTerms, 5, jme);
  const double theta = to360(s.heliocentricLongitudeDegrees + 180);  // geocentric
  const double beta = -s.heliocentricLatitudeDegrees;
  const Nutation n = nutation(jce);
  s.nutationLongitudeDegrees = n.longitudeDegrees;
  s.nutationObliquityDegrees = n.obliquityDegrees;
  s.obliquityDegrees = meanObliquityArcSeconds(jme) / 3600 + n.obliquityDegrees;
  const double aberration = -20.4898 / (3600 * s.radiusAu);
  const double lambda = theta + n.longitudeDegrees + aberration;  // apparent longitude
  const double meanSidereal = to360(280.46061837 + 360.98564736629 * (s.julianDay - kJ2000) +
                                    jc * jc * (0.000387933 - jc / 38710000));
  s.greenwichSiderealDegrees =
      to360(meanSidereal + n.longitudeDegrees * cosDeg(s.obliquityDegrees));
  const double e = s.obliquityDegrees;
  s.rightAscensionDegrees = to360(
      std::atan2(sinDeg(lambda) * cosDeg(e) - std::tan(beta * kDegree) * sinDeg(e), cosDeg(lambda)) /
      kDegree);
  s.declinationDegrees =
      std::asin(sinDeg(beta) * cosDeg(e) + cosDeg(beta) * sinDeg(e) * sinDeg(lambda)) / kDegree;
  return s;
}

double deltaTFor(double unixSeconds, double deltaT) {
  return std::isnan(deltaT) ? deltaTSeconds(decimalYear(unixSeconds)) : deltaT;
}

}  // namespace

SolarPosition solarPosition(double unixSeconds, const Observer& observer, double deltaT) {
  SolarPosition p{};
  p.terms = geocentric(unixSeconds, deltaTFor(unixSeconds, deltaT));
  const SpaTerms& s = p.terms;
  const double phi = observer.latitudeDegrees;
  p.hourAngleDegrees =
      to360(s.greenwichSiderealDegrees + observer.longitudeDegrees - s.rightAscensionDegrees);
  const double h = p.hourAngleDegrees, delta = s.declinationDegrees;
  // 3.12: parallax in right ascension and declination, the observer off the Earth's centre.
  const double xi = 8.794 / (3600 * s.radiusAu);
  const double u = std::atan(0.99664719 * std::tan(phi * kDegree));
  const double x = std::cos(u) + observer.heightMeters / 6378140 * cosDeg(phi);
  const double y = 0.99664719 * std::sin(u) + observer.heightMeters / 6378140 * sinDeg(phi);
  const double deltaAlpha =
      std::atan2(-x * sinDeg(xi) * sinDeg(h), cosDeg(delta) - x * sinDeg(xi) * cosDeg(h));
  const double deltaPrime =
      std::atan2((sinDeg(delta) - y * sinDeg(xi)) * std::cos(deltaAlpha),
                 cosDeg(delta) - x * sinDeg(xi) * cosDeg(h));
  const double hPrime = h * kDegree - deltaAlpha;
  // 3.14-3.15: elevation without refraction, and the azimuth from north.
  p.elevationDegrees = std::asin(sinDeg(phi) * std::sin(deltaPrime) +
                                 cosDeg(phi) * std::cos(deltaPrime) * std::cos(hPrime)) /
                       kDegree;
  const double fromSouth = std::atan2(
      std::sin(hPrime), std::cos(hPrime) * sinDeg(phi) - std::tan(deltaPrime) * cosDeg(phi));
  p.azimuthDegrees = to360(fromSouth / kDegree + 180);
  return p;
}

double refractionDegrees(double elevationDegrees, double pressureMillibars,
                         double temperatureCelsius) {
  constexpr double kSunRadiusDegrees = 0.26667, kRefractionAtHorizonDegrees = 0.5667;
  if (elevationDegrees < -(kSunRadiusDegrees + kRefractionAtHorizonDegrees)) return 0;
  return pressureMillibars / 1010 * 283 / (273 + temperatureCelsius) * 1.02 /
         (60 * std::tan((elevationDegrees + 10.3 / (elevationDegrees + 5.11)) * kDegree));
}

glm::dvec3 sunDirectionEcef(double unixSeconds) {
  const SpaTerms s = geocentric(unixSeconds, deltaTFor(unixSeconds, kModelDeltaT));
  // The Sun stands over the longitude where the local hour angle is 0: α − ν.
  const double longitude = (s.rightAscensionDegrees - s.greenwichSiderealDegrees) * kDegree;
  const double latitude = s.declinationDegrees * kDegree;
  return {std::cos(latitude) * std::cos(longitude), std::cos(latitude) * std::sin(longitude),
          std::sin(latitude)};
}

}  // namespace globe::sun
