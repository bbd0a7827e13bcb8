// CPU mesh of one terrain tile (no GL): float vertex offsets from a double ECEF centre, normals,
// skirts, and the one triangle index buffer that every tile of a block size shares.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/edge_heights.hpp"
#include "terrain/height_block.hpp"

namespace globe::terrain {

// Interleaved vertex layout, kTileVertexFloats floats per vertex:
//   [0..2] position: offset from TileMesh::centerEcefMeters, metres (ECEF axes)
//   [3..5] normal: unit, ECEF axes, from the heights (see buildTileMesh)
//   [6]    colour height, metres: the land height, or under water the sea floor's (0 m where its
//          depth is unknown), whichever surface the block's `sea` draws (see buildTileMesh)
//   [7]    sea flag: 1 where the sample is water (terrain::isWater), else 0; land below sea level
//          is land
//   [8..9] imagery uv, TILE-LOCAL: u = column/(N-1) growing east, v = row/(N-1) growing south,
//          so (0,0) is the tile's north-west corner and (1,1) its south-east corner. A global
//          equirectangular image maps with u_global = (west+180°+u·width)/360°,
//          v_global = (90°-north+v·height)/180°; the renderer does that per tile.
//   [10..12] coarse normal: on the tile's edges, the normal the next coarser level's mesh has
//          there (between its vertices, the normalised mean of the two around); elsewhere the
//          normal. Lit with it where the neighbour across that edge is coarser, a tile's edge
//          shades like the neighbour's, so no lighting step shows at a level change.
inline constexpr uint32_t kTileVertexFloats = 13;
// Drawn positions are whole multiples of a power of two per level, vertexQuantumMeters (1 m at
// level 0, 0.06 mm at level 14), and a mesh's centre of a coarser one, originQuantumMeters (256
// times that): then the tile's float offsets from its centre are exact (a level-0 tile spans
// under 2^24 m), and so is the centre's offset from an eye rounded to the origin quantum
// (terrain/tile_transform.hpp) within 2^24 of those (4.3e9 m / 2^level, beyond the farthest a
// tile of the level is drawn). Two tiles of one level that share an edge then compute
// bit-identical positions for its vertices, and the rasteriser closes the seam exactly (no
// sliver, no overlap).
inline constexpr double kLevelZeroVertexQuantumMeters = 1.0;
inline constexpr double kOriginQuantumPerVertexQuantum = 256.0;
double vertexQuantumMeters(uint32_t level);
double originQuantumMeters(uint32_t level);
// `position` rounded to the nearest multiple of `quantumMeters` (a power of two) per axis.
glm::dvec3 quantizedEcefMeters(const glm::dvec3& position, double quantumMeters);
inline constexpr uint32_t kTileVertexPositionOffset = 0;
inline constexpr uint32_t kTileVertexNormalOffset = 3;
inline constexpr uint32_t kTileVertexHeightOffset = 6;
inline constexpr uint32_t kTileVertexSeaOffset = 7;
inline constexpr uint32_t kTileVertexUvOffset = 8;
inline constexpr uint32_t kTileVertexCoarseNormalOffset = 10;

// The four edges of a tile, in the order their skirt vertices are stored.
enum class TileEdge : uint32_t { North = 0, South = 1, West = 2, East = 3 };

// Vertex order: the N×N grid row-major first (row 0 = north edge, column 0 = west edge), then,
// when the mesh has skirts, 4·N skirt vertices, edge by edge in TileEdge order, N per edge:
// North and South run west→east (k = column), West and East run north→south (k = row). Each skirt
// vertex sits straight below its edge vertex (along the ellipsoid normal) and copies its normal,
// height, sea flag and uv.
constexpr uint32_t gridVertexIndex(uint32_t row, uint32_t column, uint32_t verticesPerSide) {
  return row * verticesPerSide + column;
}
constexpr uint32_t skirtVertexIndex(TileEdge edge, uint32_t k, uint32_t verticesPerSide) {
  return verticesPerSide * verticesPerSide + static_cast<uint32_t>(edge) * verticesPerSide + k;
}
// The grid vertex skirt vertex (edge, k) hangs from: row 0 or N−1 at column k, or column 0 or
// N−1 at row k.
constexpr uint32_t edgeGridIndex(TileEdge edge, uint32_t k, uint32_t verticesPerSide) {
  const uint32_t last = verticesPerSide - 1;
  switch (edge) {
    case TileEdge::North:
      return gridVertexIndex(0, k, verticesPerSide);
    case TileEdge::South:
      return gridVertexIndex(last, k, verticesPerSide);
    case TileEdge::West:
      return gridVertexIndex(k, 0, verticesPerSide);
    case TileEdge::East:
      return gridVertexIndex(k, last, verticesPerSide);
  }
  return 0;
}
constexpr uint32_t tileVertexCount(uint32_t verticesPerSide, bool withSkirts) {
  return verticesPerSide * verticesPerSide + (withSkirts ? 4 * verticesPerSide : 0);
}

struct TileMesh {
  glm::dvec3 centerEcefMeters{0.0};  // midpoint of the vertices' bounding box (skirts included)
  std::vector<float> vertices;       // tileVertexCount(...) · kTileVertexFloats floats
  uint32_t verticesPerSide = 0;
  bool hasSkirts = false;
  EdgeHeightHashes edgeHeightHashes{};  // of the block (edge_heights.hpp): where a skirt is needed
  // A TIN tile's own triangles (tin_mesh.hpp), skirts included and always drawn; empty for a
  // grid, which draws the shared buildGridIndices.
  std::vector<uint32_t> indices;

  uint32_t vertexCount() const {
    return static_cast<uint32_t>(vertices.size() / kTileVertexFloats);
  }
};

// The exact double ECEF position buildTileMesh gives grid vertex (row, column) of `grid` at
// `heightMeters` (use the block's surfaceHeightMetersAt): the BlockGrid longitude/latitude in
// exact degrees; latitude ±90° lands exactly on the polar axis. Neighbouring tiles' shared
// vertices are bit-identical (same degrees, same height). Collision can use it to match the mesh.
glm::dvec3 tileVertexEcefMeters(const geo::Ellipsoid& ellipsoid, const BlockGrid& grid,
                                uint32_t row, uint32_t column, double heightMeters);

// The same for a vertex of the tile's level in or around it, row and column in
// [-kApronWidth, N+kApronWidth-1]: outside the tile at BlockGrid::wrappedVertex's place (the
// vertex the neighbour holds, across ±180° and the poles too).
glm::dvec3 levelVertexEcefMeters(const geo::Ellipsoid& ellipsoid, const BlockGrid& grid, int row,
                                 int column, double heightMeters);

// Where buildTileMesh draws grid vertex (row, column): tileVertexEcefMeters rounded to the
// tile level's vertexQuantumMeters, so neighbours draw their shared vertices at the same place.
glm::dvec3 drawnVertexEcefMeters(const geo::Ellipsoid& ellipsoid, const BlockGrid& grid,
                                 uint32_t row, uint32_t column, double heightMeters);

// Builds the mesh of `tile` from its block (a block with a TIN: buildTinMesh, tin_mesh.hpp). A
// block whose size is not 2^k+1 or whose height array does not hold N² samples gives an empty
// mesh (no vertices).
// - Positions: drawnVertexEcefMeters of block.surfaceHeightMetersAt (water at 0 m, or at its sea
//   floor when block.sea is SeaSurface::SeaFloor: what collision reads too), minus the double
//   centre, stored as float. Shared edge vertices of neighbouring tiles are therefore bit-identical
//   in double; the float offsets reconstruct them to about 2^-24 of the tile's extent (< 1 cm from
//   level 8). Vertices at latitude ±90° are placed exactly on the polar axis (x = y = 0): a pole
//   row collapses to one point wherever the row's heights are equal.
// - Normals: central differences of the double ECEF positions, n = normalize((P[i+1][j] −
//   P[i−1][j]) × (P[i][j+1] − P[i][j−1])), on the tile's edges with the apron's vertices
//   (BlockGrid::wrappedVertex at the apron's heights), so neighbours of one level compute
//   identical normals for their shared vertices. A block without an apron (an old pyramid) takes
//   one-sided differences on its edges. Where that is degenerate (a collapsed pole row) or
//   points below the horizon, the ellipsoid normal is used: never NaN.
// - Skirts (skirtDepthMeters > 0): each edge vertex is repeated at height − skirtDepthMeters;
//   recommendedSkirtDepthMeters gives a depth that closes cracks against coarser neighbours.
// - A block made from its parent's (upsampled_block.hpp) brings its own shading: its
//   shadingNormals (also its edges' coarser normals: the parent is the coarser level),
//   colorMeters and waterFraction.
TileMesh buildTileMesh(const geo::TileId& tile, const HeightBlock& block,
                       const geo::Ellipsoid& ellipsoid, double skirtDepthMeters);

// The normals buildTileMesh gives the grid's vertices, row-major (N² of them).
std::vector<glm::dvec3> gridVertexNormals(const geo::TileId& tile, const HeightBlock& block,
                                          const geo::Ellipsoid& ellipsoid);

// Skirt depth for a tile: deep enough to hide the crack against a neighbour up to one level
// coarser. With s the tile's vertex spacing along a meridian in metres, the coarser neighbour's
// edge is a chord of length 2s, sagging (2s)²/(8a) below the curved fine edge, and its linear
// interpolation misses the fine heights by at most min(2s, 9000 m) (slopes ≤ 45°; 9000 m bounds
// any relief on earth). depth = (2s)²/(8a) + min(2s, 9000 m): ~153 m at level 14, ~9 km at
// level 6, ~131 km at level 0.
double recommendedSkirtDepthMeters(uint32_t level, uint32_t verticesPerSide,
                                   const geo::Ellipsoid& ellipsoid);

// The triangle list shared by all tiles with this many vertices per side, as indices into the
// vertex order above. Triangles are counter-clockwise seen from outside (above the surface for the
// grid, from outside the tile for the skirts), so back-face culling may be enabled.
// DIAGONAL RULE (collision must use the same): each quad (i, j) — vertices (i, j), (i, j+1),
// (i+1, j), (i+1, j+1), row i growing south, column j growing east — is split along the diagonal
// from (i, j) to (i+1, j+1), the north-west to south-east diagonal, into the triangles
// {(i, j), (i+1, j), (i+1, j+1)} (south-west half) and {(i, j), (i+1, j+1), (i, j+1)}
// (north-east half), emitted in that order, quads row-major: triangle 2·(i·(N−1)+j) is the
// south-west half. Then, with skirts, 2·(N−1) triangles per edge in TileEdge order, each
// segment k..k+1 joining edge vertices k, k+1 and their skirt vertices.
std::vector<uint32_t> buildGridIndices(uint32_t verticesPerSide, bool withSkirts);

}  // namespace globe::terrain
