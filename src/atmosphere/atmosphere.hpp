// Earth's air as physically based sky models describe it (Bruneton and Neyret 2008; Hillaire
// 2020, "A Scalable and Production Ready Sky and Atmosphere Rendering Technique"): Rayleigh
// scattering by molecules, Mie scattering and absorption by aerosols, ozone absorption, each
// with its density profile, between the ground (6,360 km from the centre) and the top of the
// atmosphere (6,460 km). GL-free and deterministic, on the CPU: the sky is precomputed here, so
// llvmpipe and a GPU draw the same picture.
#pragma once

#include <glm/vec3.hpp>

namespace globe::atmosphere {

struct Atmosphere {
  double groundRadiusMeters = 6'360'000.0;
  double topRadiusMeters = 6'460'000.0;
  glm::dvec3 rayleighScatteringPerMeter{5.802e-6, 13.558e-6, 33.1e-6};
  double rayleighScaleHeightMeters = 8'000.0;
  double mieScatteringPerMeter = 3.996e-6;
  double mieExtinctionPerMeter = 4.440e-6;
  double mieScaleHeightMeters = 1'200.0;
  double mieAsymmetry = 0.8;  // Cornette-Shanks phase g
  glm::dvec3 ozoneAbsorptionPerMeter{0.650e-6, 1.881e-6, 0.085e-6};
  double ozoneCentreMeters = 25'000.0;  // a tent of 15 km half-width around it
  double ozoneHalfWidthMeters = 15'000.0;
  glm::dvec3 groundAlbedo{0.3, 0.3, 0.3};
};

// Scattering and extinction coefficients (per metre) at an altitude above the ground.
struct Medium {
  glm::dvec3 rayleighScattering{0.0};
  double mieScattering = 0.0;
  glm::dvec3 extinction{0.0};
};
Medium mediumAt(const Atmosphere& atmosphere, double altitudeMeters);

// Phase functions (per steradian) of the angle's cosine between the light and the view.
double rayleighPhase(double cosine);
double miePhase(double cosine, double asymmetry);

// Distance along a ray from radius r with zenith cosine mu to the sphere of `radius` (the far
// intersection when leaving it, the near one when entering from outside); negative: none.
double distanceToSphere(double r, double mu, double radius);
// Whether that ray meets the ground.
bool hitsGround(const Atmosphere& atmosphere, double r, double mu);

// Transmittance from radius r along zenith cosine mu to the top of the atmosphere (0 where the
// ray meets the ground), integrated numerically.
glm::dvec3 transmittanceToTop(const Atmosphere& atmosphere, double r, double mu);

}  // namespace globe::atmosphere
