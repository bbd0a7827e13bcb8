// Aerial perspective: what the air between the eye and the ground takes away from the ground's
// colour (transmittance, per colour channel) over a straight path between two heights. The
// terrain shader evaluates the same closed form per vertex under the real Sun (--time), and adds
// the sky's horizon colour in that direction for what the air scatters in: distant ridges turn
// blue and pale, as they do, and more so in blue than in red.
#pragma once

#include <glm/vec3.hpp>

#include "atmosphere/atmosphere.hpp"

namespace globe::atmosphere {

// ∫ exp(−h(s)/H) ds over a straight path of `lengthMeters` from height h0 to h1 (heights change
// linearly along it: the flat-air closed form; the chord's sag below that line over the curved
// ground, d²/8R, is left out: within 2 % of the spherical integral up to ~30 km near the ground,
// 5 % at 60 km, and for vertical paths from space). Heights below 0 count as 0.
double exponentialPathMeters(double fromHeightMeters, double toHeightMeters, double lengthMeters,
                             double scaleHeightMeters);

// exp(−(Rayleigh scattering + Mie extinction) over that path), per channel; ozone, a few
// thousandths over such paths, is left out.
glm::dvec3 aerialTransmittance(const Atmosphere& atmosphere, double fromHeightMeters,
                               double toHeightMeters, double lengthMeters);

}  // namespace globe::atmosphere
