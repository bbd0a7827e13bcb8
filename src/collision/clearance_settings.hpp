// How far above the terrain the camera is kept: the eye's desired clearance, its hard floor, the
// near plane's corners, and how fast a camera is raised when finer terrain appears under it.
#pragma once

namespace globe::collision {

// Defaults, and why:
// - eyeMeters = 2 m: the responses place the eye here. The renderer's near plane is a quarter of
//   the clearance (camera::projectionForHeight), 0.5 m at 2 m, so the near plane is 1.5 m above
//   flat ground; QOTCD's < 1 mm below the drawn surface is far inside it.
// - minimumEyeMeters = 2 m: the hard floor applied at once when the surface rises under the eye
//   (finer tiles): the eye clearance itself, so the camera is never nearer the ground than it
//   (a lower floor, with the smooth raise between it and eyeMeters, is still possible). Gliding
//   cameras (camera/terrain_glide.hpp) keep a margin above it, so a finer tile rarely needs it.
// - nearPlaneMeters = 0.5 m: the near plane's corners (~0.8 m from the eye at 45 deg / 16:9 and
//   a 0.5 m near) stay this far above the drawn surface, so looking down a steep slope cannot
//   cut it (the paper's Fig. 6(c)).
// - lateralMarginMeters = 0.1 m: no drawn triangle comes nearer the eye than the near plane's
//   corners are (~0.65 m at a 0.5 m near) plus this, in any direction (lateral_clearance.hpp),
//   so beside a steep wall neither the near plane nor the view up to it is inside the terrain.
// - raise: exponential approach with time constant 0.25 s, at most 4 m/s: a 1 m gap closes to
//   1 cm in ~1.15 s (35 frames at 30 Hz; then it snaps), the first frame moving ~0.12 m.
// A camera pushed out of the terrain goes this much beyond the required clearance (so rounding
// does not leave it a hair inside), in at most this many pushes (each re-measures the terrain).
inline constexpr double kClearancePushMarginMeters = 1e-3;
inline constexpr int kMaximumClearancePushes = 4;

struct ClearanceSettings {
  double eyeMeters = 2.0;
  double minimumEyeMeters = 2.0;
  double nearPlaneMeters = 0.5;
  double lateralMarginMeters = 0.1;
  double raiseTimeConstantSeconds = 0.25;
  double maxRaiseRateMetersPerSecond = 4.0;
};

}  // namespace globe::collision
