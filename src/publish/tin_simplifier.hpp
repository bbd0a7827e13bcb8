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

// The largest |interpolated − sample| over every grid sample (what simplifyGrid bounds).
double maxTinErrorMeters(const std::vector<double>& heightsMeters, uint32_t side,
                         const GridTin& tin);

// The same for samples with 3D positions (metres, any frame: ECEF for a tile on the globe, so
// that the flat triangles' sag under the curved surface counts too): each sample within
// maxErrorMeters of the triangle's point at the sample's place in the grid.
GridTin simplifyGridPositions(const std::vector<std::array<double, 3>>& positionsMeters,
                              uint32_t side, double maxErrorMeters);
double maxTinDistanceMeters(const std::vector<std::array<double, 3>>& positionsMeters,
                            uint32_t side, const GridTin& tin);

}  // namespace globe::publish
