// The TIN simplifier's grid and error measure (publish/tin_simplifier): grid places, the
// samples' positions, and how far a triangle of a TIN lies from the grid's surface.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "publish/tin_simplifier.hpp"

namespace globe::publish::tin {

// Grid coordinates: x the column (east), y rows from the south (north up), so that
// counter-clockwise is positive as in the output.
struct GridPoint {
  int x, y;
};

inline int64_t orient(GridPoint a, GridPoint b, GridPoint c) {
  return int64_t{b.x - a.x} * (c.y - a.y) - int64_t{b.y - a.y} * (c.x - a.x);
}

// Positive where d lies inside the circle through the counter-clockwise a, b, c, zero on it.
// Exact: the coordinates are small integers.
int64_t inCircle(GridPoint a, GridPoint b, GridPoint c, GridPoint d);

using Position = std::array<double, 3>;

// The distance between a sample's position and the triangle's point at the sample's grid place
// (the weights over the corners' positions, wSum their total).
double distanceMeters(const std::array<int64_t, 3>& w, int64_t wSum,
                      const std::array<Position, 3>& corners, const Position& sample);

// The samples' positions and the grid's shape every pass works on.
struct Grid {
  const std::vector<Position>& positions;
  int side;
  // Whether the surface between samples counts: the grid's own triangles, each cell split from
  // north-west to south-east as globe draws it.
  bool betweenSamples = false;
  // The samples in ECEF, where a flat triangle's sag under the curved globe counts; null for a
  // plain height field.
  const std::vector<Position>* ecef = nullptr;
  // The heights with a ring of the neighbours' samples ((side + 2)², rows from the north), so
  // that a side's vertices can depend on the cells on both sides of it; null without.
  const std::vector<double>* apronHeights = nullptr;

  double apronHeightAt(int x, int y) const {  // x, y in [-1, side]
    return (*apronHeights)[static_cast<size_t>(side - y) * (side + 2) + static_cast<size_t>(x + 1)];
  }
  // How far the cell with south-west corner (x, y) bends: its two diagonals' midpoints apart.
  // A TIN edge along the other diagonal misses the drawn surface by this at the cell's centre.
  double cellTwistMeters(int x, int y) const {
    return std::fabs(apronHeightAt(x, y + 1) + apronHeightAt(x + 1, y) - apronHeightAt(x, y) -
                     apronHeightAt(x + 1, y + 1)) /
           2;
  }

  const Position& positionAt(int x, int y) const {
    return positions[static_cast<size_t>(side - 1 - y) * side + x];
  }
  bool onBorder(int x, int y) const { return x == 0 || y == 0 || x == side - 1 || y == side - 1; }
  uint32_t sampleOf(GridPoint p) const {
    return static_cast<uint32_t>((side - 1 - p.y) * side + p.x);
  }
};

// How far a flat triangle through these samples lies below the globe's curve at most: the cap
// under its circumscribed circle, r² / 2R on the polar radius (the smaller: more sag). A
// triangle flat in ECEF (two corners at a pole) sags as its longest side's chord, L² / 8R.
double sagMeters(const Grid& grid, const std::array<GridPoint, 3>& v);

struct WorstSample {
  double errorMeters = -1;
  GridPoint at{-1, -1};   // the sample to insert for it; (-1, -1) when there is none
  GridPoint alt{-1, -1};  // another, should `at` be a vertex already
};

struct Crossing {
  double errorMeters = -1;
  double x = 0, y = 0;
  GridPoint from{-1, -1}, to{-1, -1};  // the grid line's samples either side of it
};

// Where the triangle's edges cross the grid's lines (columns, rows and the cells' north-west to
// south-east diagonals), the distance between the edge (flat between its corners) and the
// grid's surface there (flat between the line's two samples): with the samples, the only places
// two piecewise-flat surfaces can be farthest apart.
Crossing worstEdgeCrossing(const Grid& grid, const std::array<GridPoint, 3>& v,
                           const std::array<Position, 3>& corners);

// The triangle's largest error and the sample to insert for it: the sample farthest from the
// triangle, or, where an edge crossing is farther (Grid::betweenSamples), the insertable sample
// nearest that crossing. Border samples are skipped where asked (the sides' own simplification
// bounds them). The first in scan order on ties, so that the result depends on the data alone.
WorstSample worstSampleIn(const Grid& grid, const std::array<GridPoint, 3>& v,
                          const std::array<Position, 3>& corners, bool skipBorder);

// Heights as positions: the grid's place in samples, the height in metres. A triangle's point
// then lies over the sample exactly, so the distance is the vertical error.
std::vector<Position> heightPositions(const std::vector<double>& heightsMeters, uint32_t side);

// The largest distance over every sample (and, with betweenSamples, every edge crossing).
double maxDistance(const Grid& grid, const GridTin& tin);

}  // namespace globe::publish::tin
