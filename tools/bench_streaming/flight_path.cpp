#include "flight_path.hpp"

#include <cmath>
#include <numbers>

#include "geo/cartographic.hpp"

namespace globe::bench {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// A loop around a centre, its radius (in degrees of latitude) growing linearly over `turns`.
void spiral(std::vector<CameraSample>& out, size_t steps, const std::string& leg,
            double centreLongitudeDegrees, double centreLatitudeDegrees, double fromRadiusDegrees,
            double toRadiusDegrees, double turns) {
  const double lonScale = 1 / std::cos(geo::degreesToRadians(centreLatitudeDegrees));
  for (size_t i = 0; i < steps; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(steps);
    const double angle = kTwoPi * turns * t;
    const double radius = fromRadiusDegrees + (toRadiusDegrees - fromRadiusDegrees) * t;
    const double heightMeters = 1100 + 450 * std::sin(3 * angle);  // dips and climbs
    out.push_back(
        {geo::degreesToRadians(centreLongitudeDegrees + radius * lonScale * std::cos(angle)),
         geo::degreesToRadians(centreLatitudeDegrees + radius * std::sin(angle)), heightMeters,
         leg});
  }
}

struct Vec3 {
  double x, y, z;
};
Vec3 unit(double lonRadians, double latRadians) {
  return {std::cos(latRadians) * std::cos(lonRadians), std::cos(latRadians) * std::sin(lonRadians),
          std::sin(latRadians)};
}
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3 normalized(const Vec3& v) {
  const double length = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return {v.x / length, v.y / length, v.z / length};
}

// Once around the great circle through a and b, starting at a, between 250 and 1450 km up.
void greatCircle(std::vector<CameraSample>& out, size_t steps, const std::string& leg,
                 const geo::Cartographic& a, const geo::Cartographic& b) {
  const Vec3 u = unit(a.longitudeRadians, a.latitudeRadians);
  const Vec3 v =
      normalized(cross(normalized(cross(u, unit(b.longitudeRadians, b.latitudeRadians))), u));
  for (size_t i = 0; i < steps; ++i) {
    const double angle = kTwoPi * static_cast<double>(i) / static_cast<double>(steps);
    const Vec3 p{std::cos(angle) * u.x + std::sin(angle) * v.x,
                 std::cos(angle) * u.y + std::sin(angle) * v.y,
                 std::cos(angle) * u.z + std::sin(angle) * v.z};
    // Low near the start and end (over Fuji), high on the far side.
    const double heightMeters = 850e3 - 600e3 * std::cos(angle);
    out.push_back({std::atan2(p.y, p.x), std::atan2(p.z, std::hypot(p.x, p.y)), heightMeters, leg});
  }
}

}  // namespace

std::vector<CameraSample> scriptedFlight(size_t stepsPerLeg) {
  std::vector<CameraSample> path;
  path.reserve(3 * stepsPerLeg);
  // Inside the fine data (137.99..139.02 E, 34.98..36.01 N), around the summit (138.73 E, 35.36 N).
  spiral(path, stepsPerLeg, "Fuji spiral", 138.5, 35.5, 0.04, 0.38, 3);
  greatCircle(path, stepsPerLeg, "world circuit", geo::Cartographic::fromDegrees(138.5, 35.5),
              geo::Cartographic::fromDegrees(-1.5, 53.0));
  spiral(path, stepsPerLeg, "Fuji loop again", 138.6, 35.4, 0.2, 0.2, 1);
  return path;
}

}  // namespace globe::bench
