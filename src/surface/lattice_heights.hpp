// The exact surface at every node of a longitude × latitude lattice (a Web-Mercator tile's pixel
// centres, a heightmap's posts): PyramidSurface::heightMeters at each, the same doubles, for a
// fraction of the cost: sines and cosines once per row and column, each block looked up and its
// vertices built once, not per point.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/result.hpp"
#include "surface/pyramid_surface.hpp"

namespace globe::surface {

// Row-major heights: index row · longitudes.size() + column. maxLevel as for heightMeters.
// Errors: unreadable packs, a position off the globe.
Result<std::vector<double>> latticeHeightsMeters(PyramidSurface& surface,
                                                 std::span<const double> longitudesRadians,
                                                 std::span<const double> latitudesRadians,
                                                 uint32_t maxLevel = kFinestLevel);

}  // namespace globe::surface
