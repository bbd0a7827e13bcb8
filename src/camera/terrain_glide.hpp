// The glide: a moving camera's height follows a smooth envelope of the ground ahead of it, so
// that the paper's response, which "aims at avoiding collisions before they occur", rarely has
// to act, and when it does the camera is already on its way up instead of scraping or bouncing.
//
// Each frame the drawn surface is read where the camera will be in the next seconds: along the
// path a script will take (the player knows it), or else along its velocity, over a distance
// that grows with speed. A point t seconds ahead needs the lift ground + eye clearance + margin -
// the camera's height there; it counts less the farther ahead it is, by what a climb at a
// bounded vertical acceleration rises in t (a t^2 / 4: half the time speeding up, half slowing),
// so a ridge ahead lifts the camera early and gently. The lift above the proposed (scripted or
// steered) height approaches the largest of these as a critically damped spring, with no
// overshoot and no oscillation, and is never less than what the ground right under the proposed
// position needs (the hard floor, exact, applied at once).
#pragma once

#include <span>

#include <glm/vec3.hpp>

#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"
#include "terrain/rendering_tile_array.hpp"

namespace globe::camera {

struct GlideSettings {
  bool enabled = true;
  double lookAheadSeconds = 3.0;  // how far ahead in time the ground is read
  int samples = 24;               // readings along the look-ahead (and one under the camera)
  double climbAccelerationMetersPerSecondSquared = 20.0;
  double marginMeters = 3.0;        // aimed at above the eye clearance (room for the spring)
  double speedMarginSeconds = 0.4;  // and this much more per m/s (30 m/s: 12 m; capped)
  double maximumMarginMeters = 50.0;
  double settleSeconds = 0.3;  // the spring's time constant (1/omega)
};

// Where the camera will be, secondsAhead from now (a scripted path's future poses).
struct GlidePoint {
  geo::Cartographic position{};
  double secondsAhead = 0.0;
};

struct GlideResult {
  double liftMeters = 0.0;        // add to the proposed height
  double targetLiftMeters = 0.0;  // what the envelope asked for
  double hardLiftMeters = 0.0;    // what the ground under the proposed position needs at least
  int samples = 0;                // surface readings
};

class TerrainGlide {
 public:
  explicit TerrainGlide(const GlideSettings& settings = {}) : settings_(settings) {}

  // The lift for a camera proposed at `proposed`, having moved by displacementEcefMeters over
  // dtSeconds, to keep eyeMeters above the drawn surface. `ahead` (may be empty) holds where
  // the camera will be next; without it the camera is taken to keep its velocity. A non-finite
  // input or a non-positive dt leaves the lift as it is.
  GlideResult update(const terrain::RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                     const geo::Cartographic& proposed, const glm::dvec3& displacementEcefMeters,
                     std::span<const GlidePoint> ahead, double dtSeconds, double eyeMeters);

  void reset() { lift_ = rate_ = 0.0; }  // a jump, a stop: no lift carried over
  double liftMeters() const { return lift_; }
  const GlideSettings& settings() const { return settings_; }

 private:
  GlideSettings settings_;
  double lift_ = 0.0;  // metres above the proposed height
  double rate_ = 0.0;  // its rate of change, m/s
};

}  // namespace globe::camera
