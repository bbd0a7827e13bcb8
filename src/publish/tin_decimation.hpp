// Vertex removal after greedy insertion (publish/tin_simplifier, step 3).
#pragma once

#include "publish/tin_grid.hpp"
#include "publish/tin_insertion.hpp"
#include "publish/tin_simplifier.hpp"

namespace globe::publish::tin {

// The inserted vertices (never the border's) collapsed onto a neighbour wherever every triangle
// stays counter-clockwise and within maxErrorMeters; the result as grid samples.
GridTin decimate(const Grid& grid, double maxErrorMeters, const Insertion& inserted);

}  // namespace globe::publish::tin
