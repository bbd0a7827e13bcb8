// Where a finer source's footprint ends inside a coarser one, the coarser surface bends to meet
// the finer edge, outside the footprint and never inside it: coarse + Δ, where Δ is the finer
// edge's difference to the coarser surface carried outwards smoothly and fading to 0 over a
// margin sized by the coarser source's cell. Carried harmonically (the smoothest surface between
// the edge and the margin, then eased so it leaves the edge level), so the edge's fine detail
// fades within its own wavelength instead of being extruded into streaks, while its broad shape
// reaches the margin. So there is no wall and
// no moat, and the finer data is drawn as it is. Where finer land meets coarser water, the bent
// surface is a shore sloping into the water: water only where the coarser surface is water and
// the bent height is at or below 0 m (sea only where something says sea).
#pragma once

#include <cstdint>
#include <vector>

#include "conditioning/coarser_sources.hpp"
#include "conditioning/dem_grid.hpp"

namespace globe::conditioning {

// The weight of the finer edge at distanceDegrees from it: 1 at it, 0 from marginDegrees on.
double bendWeight(double distanceDegrees, double marginDegrees);

// The coarser sample (block encoding) raised or lowered by deltaMeters (sea floors take part
// where measured, 0 m where not): water where the coarser sample is water and the result is at
// most 0 m, otherwise land, never bent below min(0 m, the coarser height) so that no dry pit
// opens beside a finer sea.
int16_t bentSample(int16_t coarseHere, double deltaMeters);

// Writes the bent coarser surface into every sample with outside[i] set (the footprint is every
// other sample), Δ solved over the outside samples within marginDegrees of the footprint (a
// degree of longitude counting as one of latitude). Returns how many samples were written.
uint64_t bendCoarserToFootprint(DemGrid& grid, const std::vector<uint8_t>& outside,
                                const CoarserSources& coarser, double marginDegrees);

}  // namespace globe::conditioning
