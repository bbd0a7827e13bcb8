// Greedy insertion into a Delaunay triangulation (publish/tin_simplifier, step 2), the sides'
// vertices (step 1) inserted first.
#pragma once

#include <vector>

#include "publish/tin_grid.hpp"

namespace globe::publish::tin {

struct Insertion {
  std::vector<GridPoint> points;
  std::vector<int> triangles;  // three indices into points each, counter-clockwise
  int fixedVertices = 0;       // points[0, fixedVertices) lie on the border
};

// The sides simplified (within half the error where the grid has an apron), then the worst sample
// inserted until every triangle is within maxErrorMeters or has no sample left to insert.
Insertion greedyInsertion(const Grid& grid, double maxErrorMeters);

}  // namespace globe::publish::tin
