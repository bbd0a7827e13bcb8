// The sky seen from one height with the Sun at one zenith angle, as an image the sky pass draws
// (render/sky_pass.hpp): azimuth from the Sun's vertical across (0 to 180°: the sky is symmetric
// about it), elevation up, with rows crowded around the horizon (Hillaire 2020's "sky-view
// LUT"). Each texel is the light scattered into a ray marched through the air: single scattering
// (Rayleigh and Mie phases, the Sun's transmittance, the Earth's shadow) plus all higher orders
// from the multiple-scattering table; blue by day, red towards a low Sun, the lit limb from space,
// black where a ray misses the air. Tone-mapped to 8 bits: 1 − exp(−exposure · radiance), then
// gamma 2.2.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "atmosphere/sky_tables.hpp"

namespace globe::atmosphere {

// Radiance reaching the eye (the Sun's illuminance = 1) along `direction` (unit, local frame: z
// up at the camera) from radius r, with the Sun towards `sun` (unit, the same frame).
glm::dvec3 skyRadiance(const SkyTables& tables, double r, const glm::dvec3& direction,
                       const glm::dvec3& sun);

// The elevation (radians) where the ground's tangent meets the view from radius r: 0 at the
// ground, negative above it.
double horizonElevation(const Atmosphere& atmosphere, double r);
// The image's row coordinate v in [0, 1] and the elevation (radians) it stands for, rows
// crowded around the horizon (v = 0.5).
double skyViewElevation(double v, double horizonElevationRadians);
double skyViewRow(double elevationRadians, double horizonElevationRadians);

inline constexpr double kSkyExposure = 12.0;
glm::dvec3 toneMapped(const glm::dvec3& radiance);  // 0..1, what is shown

struct SkyViewImage {
  int width = 0, height = 0;
  double cameraRadiusMeters = 0.0;
  double horizonElevationRadians = 0.0;
  std::vector<uint8_t> rgba;                // rows bottom (v = 0) first, as GL textures are
  glm::dvec3 at(double u, double v) const;  // 0..1 colour, bilinear (for the fog and tests)
};
SkyViewImage skyView(const SkyTables& tables, double cameraRadiusMeters, double sunZenithCosine,
                     int width = 128, int height = 96);

}  // namespace globe::atmosphere
