// tileset.json (3D Tiles 1.1) for a building quadtree: one tile per cell, refined by ADD (a
// cell's buildings stay drawn as its children's are added), each with a bounding region around
// everything under it and, where it holds buildings, a GLB content (tiles/LEVEL/X/Y.glb).
// A tile's geometric error is a twentieth of its cell's width (what drawing none of its
// children's smaller buildings leaves out), 0 at the leaves.
#pragma once

#include <span>
#include <string>

#include "buildings/building_quadtree.hpp"

namespace globe::buildings {

// What a cell's own buildings cover (degrees; heights above the ellipsoid, m).
struct CellBounds {
  bool empty = true;
  ExtentDegrees extent;
  double minHeightMeters = 0, maxHeightMeters = 0;
};

// The content file of a cell, relative to the tileset's folder.
std::string contentUri(const QuadtreeCell& cell);

// The tileset's JSON text; `own[i]` are cells[i]'s own buildings' bounds.
std::string tilesetJson(std::span<const QuadtreeCell> cells, std::span<const CellBounds> own);

}  // namespace globe::buildings
