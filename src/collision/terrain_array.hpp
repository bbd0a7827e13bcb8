// Collision consumes the rendering tile array that terrain defines (the tiles drawn this frame,
// their blocks and the index that finds the tile under a point): its names, in collision's.
#pragma once

#include "terrain/rendering_tile_array.hpp"
#include "terrain/tile_containment.hpp"

namespace globe::collision {

using terrain::ArrayTile;
using terrain::containsClosed;
using terrain::hasReadableBlock;
using terrain::longitudeInTile;
using terrain::makeArrayTile;
using terrain::makeQueryPoint;
using terrain::Pole;
using terrain::QueryPoint;
using terrain::RenderingTileArray;
using terrain::selectionKey;
using terrain::TileLookup;

}  // namespace globe::collision
