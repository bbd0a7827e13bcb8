// The one rule that turns a source's 2×2 samples around a point into a block sample, shared by
// the tiler (every vertex) and the conditioning (what a coarser source says at a point), so the
// blend at a source's edge aims at exactly the surface the tiler draws beyond it.
//  - land all round: bilinear;
//  - water all round: water over the bilinear sea floor;
//  - a coast where the water has a measured floor (ETOPO): the zero contour of the bilinear
//    land-and-floor surface is the coastline, so the ground meets the sea at 0 m with no cliff;
//  - a coast where the water's depth is unknown (GTOPO30, SRTM): the nearest sample decides, and
//    land next to it slopes to 0 m.
#pragma once

#include <array>
#include <cstdint>

namespace globe::conditioning {

// samples: north-west, north-east, south-west, south-east; tu, tv in [0, 1] eastwards/southwards.
int16_t interpolateSample(const std::array<int16_t, 4>& samples, double tu, double tv);

// A land height as a block sample: rounded, clamped to the land range, never -9999.
int16_t landSample(double heightMeters);

}  // namespace globe::conditioning
