// A terrain block: N×N vertex heights of one tile, in GTOPO30 encoding (int16 metres, -9999 = no
// data).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

namespace globe::terrain {

// Block samples are GTOPO30 heights (int16 metres) with one extension for bathymetry:
//   -9999                  water, floor depth unknown (GTOPO30's no data: sea)
//   -32767 .. -20001       water over a sea floor at (sample + 20000) metres, -12767..-1 m
//   anything else          land at that height, below sea level included (Dead Sea, polders)
// The tiler decides which samples are water (sea connected to open sea, see docs/conditioning.md);
// the viewer draws water as a surface at 0 m (MSL) and collides with it, unless the sea floor is
// asked for.
inline constexpr int16_t kNoDataHeight = -9999;
inline constexpr int16_t kSeaFloorCodeOffset = -20000;
inline constexpr int16_t kDeepestSeaFloorMeters = -12767;
inline constexpr int16_t kLowestLandMeters = -12000;  // land heights are clamped above this

constexpr bool isWater(int16_t sample) {
  return sample == kNoDataHeight || sample <= kSeaFloorCodeOffset - 1;
}

// Sea floor height of a water sample (0 m when unknown); the land height for land.
constexpr double seaFloorMeters(int16_t sample) {
  if (sample == kNoDataHeight) return 0.0;
  if (sample <= kSeaFloorCodeOffset - 1) return static_cast<double>(sample - kSeaFloorCodeOffset);
  return static_cast<double>(sample);
}

// Water sample for a sea floor at floorMeters (rounded; >= -0.5 m or NaN: depth unknown).
constexpr int16_t encodeWater(double floorMeters) {
  if (!(floorMeters < -0.5)) return kNoDataHeight;
  const double clamped =
      floorMeters < kDeepestSeaFloorMeters ? kDeepestSeaFloorMeters : floorMeters;
  const auto depth = static_cast<int>(clamped - 0.5);  // round half away from zero (negative)
  return static_cast<int16_t>(kSeaFloorCodeOffset + depth);
}

// Vertices per side: 2^k + 1 so that a parent's vertices are every other vertex of its children.
bool isValidBlockSize(uint32_t verticesPerSide);

// What the viewer and collision take as the ground over water.
enum class SeaSurface : uint8_t {
  Water,     // the water surface at 0 m (default)
  SeaFloor,  // the sea floor (bathymetry) where known, 0 m where not
};

// Height of a block sample as a surface height: water is 0 m, or its floor with SeaFloor.
constexpr double surfaceHeightMeters(int16_t sample, SeaSurface sea = SeaSurface::Water) {
  if (!isWater(sample)) return static_cast<double>(sample);
  return sea == SeaSurface::Water ? 0.0 : seaFloorMeters(sample);
}

struct HeightRange {
  int16_t minimumMeters = 0;
  int16_t maximumMeters = 0;
  void include(const HeightRange& other);
};

// The apron: the band of samples kApronWidth vertices wide around a block, i.e. the
// neighbouring tiles' vertices next to its edges, so a block's edge normals can use central
// differences that agree with its neighbours' at its own level (1 vertex out) and at the next
// coarser level (2 vertices out: every other vertex is the parent level's). Band order, rows and
// columns relative to the block (-w..N+w-1 for width w): the north rows (-w..-1, columns
// -w..N+w-1), the south rows (N..N+w-1, same columns), then per block row 0..N-1 the west
// columns (-w..-1) and then per block row the east columns (N..N+w-1). Beyond a pole the band
// holds the vertices mirrored over the pole.
inline constexpr int kApronWidth = 2;
constexpr size_t apronSampleCount(uint32_t verticesPerSide) {
  const size_t n = verticesPerSide, w = kApronWidth;
  return (n + 2 * w) * (n + 2 * w) - n * n;
}
// Index into the band of (row, column), both in [-w, N+w-1], outside the block.
constexpr size_t apronIndex(int row, int column, uint32_t verticesPerSide) {
  const auto n = static_cast<int>(verticesPerSide);
  constexpr int w = kApronWidth;
  const int span = n + 2 * w;  // a north or south row
  if (row < 0) return static_cast<size_t>((row + w) * span + column + w);
  if (row >= n) return static_cast<size_t>((w + row - n) * span + column + w);
  if (column < 0) return static_cast<size_t>(2 * w * span + row * w + column + w);
  return static_cast<size_t>(2 * w * span + n * w + row * w + column - n);
}

class TinTile;  // tin_tile.hpp

// Vertex (row, column): row 0 is the north edge, column 0 the west edge.
struct HeightBlock {
  uint32_t verticesPerSide = 0;
  std::vector<int16_t> heights;        // row-major, verticesPerSide^2 samples
  SeaSurface sea = SeaSurface::Water;  // the surface the view asked for, set when loaded
  // apronSampleCount(verticesPerSide) samples, or empty (pyramids from before pack version 3).
  std::vector<int16_t> apron{};
  // A block made from its parent's surface (terrain/upsampled_block.hpp) keeps that surface's
  // heights exactly, which int16 samples cannot: the surface heights (metres, `sea` applied) of
  // the grid and of the apron, in the orders above. Empty for blocks read from a pyramid.
  std::vector<double> exactSurfaceMeters{};
  std::vector<double> exactApronSurfaceMeters{};
  // Such a block is also shaded as its parent's triangles shade that ground, so that a refined
  // tile looks like the one it refines: per grid vertex, the parent's normal (unit, ECEF), the
  // height its colour shows and its water fraction (0..1), interpolated linearly along the
  // parent's edges. Empty for blocks read from a pyramid (tile_mesh.hpp derives them).
  std::vector<glm::vec3> shadingNormals{};
  std::vector<float> colorMeters{};
  std::vector<float> waterFraction{};
  // A tile its source gives as a TIN (quantized-mesh): its triangles as the producer simplified
  // them, with their triangle index. Then the TIN is the surface: the mesh draws its triangles
  // (tile_mesh.hpp) and collision reads them (collision/qotcd_height.hpp, exact_surface.hpp);
  // the grid above holds the TIN sampled at its vertices, for what needs a grid (children made
  // from this tile, normals at its edges, sunlight). Built where the tile loads; shared, never
  // changed.
  std::shared_ptr<const TinTile> tin{};

  int16_t at(uint32_t row, uint32_t column) const {
    return heights[static_cast<size_t>(row) * verticesPerSide + column];
  }
  double surfaceHeightMetersAt(uint32_t row, uint32_t column) const {
    if (!exactSurfaceMeters.empty()) {
      return exactSurfaceMeters[static_cast<size_t>(row) * verticesPerSide + column];
    }
    return surfaceHeightMeters(at(row, column), sea);
  }
  bool hasApron() const { return apron.size() == apronSampleCount(verticesPerSide); }
  // The surface height at (row, column) in [-kApronWidth, N+kApronWidth-1] (requires hasApron()
  // outside the block).
  double surfaceHeightMetersWithApron(int row, int column) const {
    const auto n = static_cast<int>(verticesPerSide);
    if (row >= 0 && row < n && column >= 0 && column < n) {
      return surfaceHeightMetersAt(static_cast<uint32_t>(row), static_cast<uint32_t>(column));
    }
    if (!exactApronSurfaceMeters.empty()) {
      return exactApronSurfaceMeters[apronIndex(row, column, verticesPerSide)];
    }
    return surfaceHeightMeters(apron[apronIndex(row, column, verticesPerSide)], sea);
  }
  // Sample (row, column) for row and column in [-kApronWidth, N+kApronWidth-1]: the block
  // inside, the apron around it (requires hasApron()).
  int16_t atWithApron(int row, int column) const {
    const auto n = static_cast<int>(verticesPerSide);
    if (row >= 0 && row < n && column >= 0 && column < n) {
      return at(static_cast<uint32_t>(row), static_cast<uint32_t>(column));
    }
    return apron[apronIndex(row, column, verticesPerSide)];
  }
};

// Range of the block's surface heights under either sea surface: the minimum with sea floors, the
// maximum with water at 0 m, so the range bounds the surface whichever the view draws.
HeightRange surfaceHeightRange(const HeightBlock& block);

}  // namespace globe::terrain
