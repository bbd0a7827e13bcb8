// Minimum-curvature interpolation in tension over a void (Briggs 1974; Smith & Wessel 1990): the
// surface through the void's surroundings that minimises (1 - T)·Σ(discrete Laplacian)² +
// T·Σ(gradient)², so slopes carry on across the border instead of bending flat at it as the
// harmonic fill (T = 1) does, without the bulges of pure minimum curvature (T = 0). Solved by
// conjugate gradients on the least-squares problem, from the harmonic fill; the result is clamped
// to the border's range (a void never fills above or below what surrounds it).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "conditioning/dem_grid.hpp"

namespace globe::conditioning {

// region and borderValue as in solveHarmonic; start: the harmonic values (region order), which
// are also the answer for samples no Laplacian reaches. Uses the two rings around the void.
std::vector<double> solveMinimumCurvature(
    const DemGrid& grid, const std::vector<uint8_t>& isVoid, const std::vector<size_t>& region,
    const std::function<double(int64_t, int64_t)>& borderValue, std::vector<double> start,
    double tension);

}  // namespace globe::conditioning
