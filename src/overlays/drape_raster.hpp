// Draws the draped overlays into one imagery tile of the geographic quadtree, with cairo
// (antialiased, even-odd fills, round joins): the terrain drapes it like any imagery layer, so
// lines and polygons lie on the drawn surface at every level of detail. Line widths are in the
// tile's texels, which the viewer draws at about a screen pixel each.
#pragma once

#include "formats/image_io.hpp"
#include "geo/tile_id.hpp"
#include "overlays/drape_set.hpp"

namespace globe::overlays {

// The tile's box in degrees widened by what the widest line spills over its edge.
DegreesBox tileReach(const geo::TileId& tile, int tileSizePixels, double maxLineWidthPixels);

// Whether anything of `set` may show on the tile (its items' boxes, also shifted by ±360°).
bool touchesTile(const DrapeSet& set, const geo::TileId& tile, int tileSizePixels);

// The tile as straight RGBA8, tileSizePixels square; pixel (r, c) is the point at
// west + c·w/(S−1), north − r·h/(S−1) (formats::ImageryPixelGrid::Edges), so neighbouring tiles
// agree along their shared edge. Transparent where nothing is drawn.
formats::ImageRgba drawTile(const DrapeSet& set, const geo::TileId& tile, int tileSizePixels);

}  // namespace globe::overlays
