#include "render/sky_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/common.hpp>

namespace globe::render {
namespace {

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

glm::vec3 mix(const glm::vec3& a, const glm::vec3& b, double t) {
  return glm::mix(a, b, static_cast<float>(t));
}

}  // namespace

SkyParameters skyAt(double cameraHeightMeters, double globeRadiusMeters) {
  double h = std::isnan(cameraHeightMeters) ? 0.0 : std::max(cameraHeightMeters, 0.0);
  h = std::min(h, 1e12);  // beyond this nothing changes
  const double radius = globeRadiusMeters > 0.0 ? globeRadiusMeters : 6'371'000.0;
  SkyParameters sky;
  // Zenith: daylight blue at the ground, deep blue at 12 km, near black at the air's top.
  const glm::vec3 groundZenith(0.24f, 0.47f, 0.85f), highZenith(0.05f, 0.13f, 0.36f);
  const glm::vec3 groundHorizon(0.72f, 0.82f, 0.93f), highHorizon(0.45f, 0.62f, 0.88f);
  const double up = smoothstep(0.0, 12'000.0, h);
  const double top = smoothstep(12'000.0, 80'000.0, h);
  sky.zenithRgb = mix(mix(groundZenith, highZenith, up), glm::vec3(0.0f), top);
  sky.horizonRgb = mix(groundHorizon, highHorizon, top);
  sky.glowRgb = glm::vec3(0.36f, 0.58f, 0.98f);
  sky.spaceBlend = static_cast<float>(smoothstep(20'000.0, 100'000.0, h));
  const double ratio = radius / (radius + h);
  sky.horizonCosine = static_cast<float>(-std::sqrt(std::max(0.0, 1.0 - ratio * ratio)));
  // Fog: 1/e of its maximum at ~150 km from the ground, further from higher up; gone above
  // ~60 km. (A view 9 km above the ground gets 0.1 % of it straight down.)
  const double visibilityMeters = 150'000.0 + 20.0 * h;
  sky.fogDensityPerMeter = static_cast<float>(1.0 / visibilityMeters);
  sky.fogMaximum = static_cast<float>(0.7 * (1.0 - smoothstep(5'000.0, 60'000.0, h)));
  return sky;
}

namespace {

// sin(elevation) of the twilight band's edges.
const double kSunBelowForNight = std::sin(-6.0 * std::numbers::pi / 180);
const double kSunAboveForDay = std::sin(4.0 * std::numbers::pi / 180);
const double kSkyBelowForNight = std::sin(-10.0 * std::numbers::pi / 180);
constexpr glm::vec3 kNightZenithRgb{0.004f, 0.006f, 0.016f};
constexpr glm::vec3 kNightHorizonRgb{0.010f, 0.014f, 0.030f};

}  // namespace

DaylightBand daylightBand() {
  return {kNightLight, static_cast<float>(kSunBelowForNight), static_cast<float>(kSunAboveForDay)};
}

float daylight(double sunUpCosine) {
  if (!std::isfinite(sunUpCosine)) return 1.0f;
  const double day = smoothstep(kSunBelowForNight, kSunAboveForDay, sunUpCosine);
  return static_cast<float>(kNightLight + (1.0 - kNightLight) * day);
}

SkyParameters skyUnderSun(const SkyParameters& day, double sunUpCosine) {
  if (!std::isfinite(sunUpCosine)) return day;
  // The sky keeps some light longer than the ground: the air above is still sunlit.
  const auto lit = static_cast<float>(smoothstep(kSkyBelowForNight, kSunAboveForDay, sunUpCosine));
  SkyParameters sky = day;
  sky.zenithRgb = glm::mix(kNightZenithRgb, day.zenithRgb, lit);
  sky.horizonRgb = glm::mix(kNightHorizonRgb, day.horizonRgb, lit);
  sky.glowRgb = day.glowRgb * lit;
  return sky;
}

}  // namespace globe::render
