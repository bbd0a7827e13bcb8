// The mesh of a TIN tile (a block with a `tin`, tin_tile.hpp): its own vertices and triangles as
// the producer simplified them, not resampled onto the grid, with skirts hanging from every edge
// vertex (a TIN's edge vertices need not match its neighbours', so its skirts are always drawn).
#pragma once

#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"
#include "terrain/height_block.hpp"
#include "terrain/tile_mesh.hpp"

namespace globe::terrain {

// Vertices: the TIN's, in its order (tin_tile.hpp's vertexEcefMeters rounded to the level's
// vertexQuantumMeters), then one skirt vertex per edge vertex, skirtDepthMeters below it.
// Normals: the producer's (quantized-mesh's oct-encoded normals) where it gave them, else the
// area-weighted mean of the triangles' around each vertex. uv: u east, 1 − v south (the grid's
// tile-local layout). Sea: the block's grid sample nearest the vertex. TileMesh::indices holds
// the triangles, counter-clockwise from above (the producer's, turned where they were not;
// degenerate ones left out), then the skirts', counter-clockwise from outside the tile. The
// edge hashes never match a neighbour's, so a grid neighbour draws its skirt too.
TileMesh buildTinMesh(const geo::TileId& tile, const HeightBlock& block,
                      const geo::Ellipsoid& ellipsoid, double skirtDepthMeters);

}  // namespace globe::terrain
