// A grid of heights as a TIN within a maximum vertical error: the fewest triangles we can find
// whose interpolated surface lies within maxErrorMeters of every grid sample.
//
// 1. Each side of the square is simplified on its own (recursive subdivision at the sample
//    farthest from the chord), from its samples alone and always walked west to east or south to
//    north: two tiles that share a side choose the same vertices on it, so no T-junction (crack)
//    opens between neighbours of one level.
// 2. Inside, greedy insertion into a Delaunay triangulation (Garland and Heckbert's, as delatin
//    does): the sample farthest from the surface is inserted until every one is within the error.
// 3. Then each inserted vertex is removed again where it can be (a half-edge collapse onto a
//    neighbour that keeps every triangle upright and every sample within the error): greedy
//    insertion keeps vertices that later insertions made unnecessary.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace globe::publish {

struct GridTin {
  // Grid samples used as vertices: row * side + column, rows from the north.
  std::vector<uint32_t> samples;
  // Three indices into `samples` each, counter-clockwise seen from above (east right, north up).
  std::vector<uint32_t> triangles;

  size_t triangleCount() const { return triangles.size() / 3; }
};

// heightsMeters: side × side (side >= 2), rows from the north. Non-finite heights are not allowed
// (the pyramid's surface has none).
GridTin simplifyGrid(const std::vector<double>& heightsMeters, uint32_t side,
                     double maxErrorMeters);

// The largest |interpolated − sample| over every grid sample (what simplifyGrid bounds: the
// error as martini and delatin define it, at the samples only).
double maxTinErrorMeters(const std::vector<double>& heightsMeters, uint32_t side,
                         const GridTin& tin);

// A tile's grid as globe draws it: the error also counts the surface between the samples (the
// grid's own triangles, each cell split from north-west to south-east: every point where a TIN
// edge crosses a grid line is checked too, and the sample nearest the worst such point inserted)
// and the flat triangles' sag under the globe's curve, from the samples' ECEF positions
// (side², rows from the north): a coarse tile's TIN must follow the Earth, not only the heights.
// apronHeightsMeters ((side + 2)², the grid and the ring of the neighbours' samples around it):
// a side also keeps each sample beside a cell, inside or beyond, that bends more than the error
// (no TIN without that sample follows the cell), which both tiles sharing the side see alike.
GridTin simplifyTileGrid(const std::vector<double>& heightsMeters,
                         const std::vector<double>& apronHeightsMeters,
                         const std::vector<std::array<double, 3>>& ecefMeters, uint32_t side,
                         double maxErrorMeters);
double maxTileTinErrorMeters(const std::vector<double>& heightsMeters,
                             const std::vector<std::array<double, 3>>& ecefMeters, uint32_t side,
                             const GridTin& tin);

}  // namespace globe::publish
