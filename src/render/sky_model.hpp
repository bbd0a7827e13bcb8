// The sky and the air between the camera and the terrain, as colours that depend only on the
// camera's height (no time, no randomness: screenshots are deterministic). GL-free: the sky pass
// and the terrain shaders take these as uniforms.
//
// Inside the air (below ~20 km the model is all "air"): a gradient from a pale horizon haze to a
// blue zenith that darkens with height, and distance fog on the terrain towards the horizon
// colour, thinning with height. From space (above ~100 km all "space"): black, with a thin blue
// glow where a view ray passes through the air around the globe's limb. In between the two blend.
#pragma once

#include <glm/vec3.hpp>

namespace globe::render {

// Thickness of the limb glow seen from space, metres: thicker than the air that scatters most of
// the light (~60 km), so that the rim shows as more than one pixel from far away.
inline constexpr double kAtmosphereHeightMeters = 150'000.0;

struct SkyParameters {
  glm::vec3 zenithRgb{0.0f};   // the sky straight up, linear 0..1
  glm::vec3 horizonRgb{0.0f};  // the sky at the horizon; also the fog's colour
  glm::vec3 glowRgb{0.0f};     // the limb glow seen from space
  float spaceBlend = 0.0f;     // 0: the air's gradient only, 1: space and its limb glow only
  // Cosine of the horizon's zenith angle: 0 on the ground, negative above it (the horizon dips).
  float horizonCosine = 0.0f;
  // Terrain fog: fraction = fogMaximum · (1 − exp(−(distance · fogDensityPerMeter)²)): squared,
  // so the ground near the camera keeps its true colours and the haze gathers towards the
  // horizon.
  float fogDensityPerMeter = 0.0f;
  float fogMaximum = 0.0f;
};

// cameraHeightMeters: above the globe's surface (NaN or negative count as 0, infinity as far
// away); globeRadiusMeters > 0 (the mean earth radius for WGS84 is fine). Never NaN.
SkyParameters skyAt(double cameraHeightMeters, double globeRadiusMeters);

// The sky under the real Sun (--time): sunUpCosine is the cosine of the Sun's zenith angle at the
// camera (the dot of the camera's up and the direction to the Sun). Day's colours while the Sun
// is up, fading through twilight (the Sun down to 6° below the horizon) to a night of deep blue
// near black; the fog (the horizon's colour) darkens with it, so the night side is not hazed.
SkyParameters skyUnderSun(const SkyParameters& day, double sunUpCosine);

// How much of the day's light reaches the ground where the Sun's zenith angle has this cosine:
// 1 with the Sun above the horizon's twilight band, the night's floor (kNightLight) once it is 6°
// below, smooth in between (the soft terminator the terrain shader draws too).
inline constexpr float kNightLight = 0.05f;
float daylight(double sunUpCosine);

// The same band for the terrain shader (u_daylightBand): the night's floor and the cosines of the
// Sun's zenith angle where night ends and day begins.
struct DaylightBand {
  float nightLight, nightCosine, dayCosine;
};
DaylightBand daylightBand();

}  // namespace globe::render
