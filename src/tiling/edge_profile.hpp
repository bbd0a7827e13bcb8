// A source's four edges as height profiles for the ground just outside it: at a distance d from
// an edge, the edge's heights averaged over a window d wide each side along it. So the coarser
// surface outside bends towards the edge's own height right at the edge, and towards its broad
// shape farther out, instead of extruding every ridge of the edge into a streak (the harmonic
// bend of conditioning/footprint_bend.hpp does the same over a grid). Heights are sea floors where
// measured, 0 m for water of unknown depth.
#pragma once

#include <cstdint>
#include <vector>

#include "core/result.hpp"
#include "rasters/raster_source.hpp"

namespace globe::tiling {

// One edge: heights at sample positions 0..n-1, linear between them.
class EdgeProfile {
 public:
  EdgeProfile() = default;
  explicit EdgeProfile(std::vector<double> heightsMeters);
  // The mean over [position − halfWindow, position + halfWindow] ∩ [0, n−1] (positions in
  // samples); the height at the clamped position when that is shorter than a thousandth.
  double meanMeters(double position, double halfWindow) const;
  bool empty() const { return heights_.empty(); }

 private:
  double integralTo(double position) const;  // of the linear profile from 0
  std::vector<double> heights_;
  std::vector<double> integral_;  // at each sample position
};

struct EdgeProfiles {
  EdgeProfile north, south, west, east;  // along columns (north, south) or rows (west, east)
};

// Reads the edges of a (conditioned) source.
Result<EdgeProfiles> readEdgeProfiles(const rasters::RasterSource& raster);

}  // namespace globe::tiling
