// Where a water mask decides land and water instead of the terrain's own sea flag: where the
// terrain's finest source is coarser than the mask. A 20' grid's sea flag, interpolated between
// vertices 37 km apart, draws coasts as staircases; a mask from land polygons draws them where the
// shoreline is. Where the terrain is about as fine (SRTM beside a 150 m mask), its own
// classification, from the heights themselves, is kept.
#pragma once

namespace globe::terrain {

// The mask decides fully where the terrain's step is at least this many mask texels...
inline constexpr double kMaskDecidesStepRatio = 3.0;
// ...and not at all where it is at most this many; linear between.
inline constexpr double kTerrainDecidesStepRatio = 1.5;

// The mask's weight (0 = the terrain's sea flag, 1 = the mask's) for terrain samples
// terrainStepDegrees apart and a mask texel maskTexelDegrees across. 1 where either is not a
// positive finite number (unknown: the mask is there to be used).
double waterMaskWeight(double maskTexelDegrees, double terrainStepDegrees);

}  // namespace globe::terrain
