// A synthetic world for the upsampled-block tests: heights as a function of the exact vertex
// position, so neighbouring tiles agree on shared vertices and aprons as tiler output does.
#pragma once

#include <cmath>
#include <cstdint>

#include "geo/cartographic.hpp"
#include "geo/tile_id.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/height_block.hpp"

namespace globe::testing {

// Hills up to ~4 km, steep ripples, sea (-9999) where the function is low; constant on the poles.
inline int16_t upsampledWorldHeight(double longitudeDegrees, double latitudeDegrees) {
  if (std::abs(latitudeDegrees) == 90.0) return 1200;
  const double lon = geo::degreesToRadians(longitudeDegrees);
  const double lat = geo::degreesToRadians(latitudeDegrees);
  const double h = 900.0 + 2000.0 * std::sin(3.0 * lon + 1.0) * std::cos(5.0 * lat) +
                   1200.0 * std::sin(90.0 * lon) * std::sin(83.0 * lat);
  if (h < -200.0) return terrain::kNoDataHeight;
  return static_cast<int16_t>(std::lround(h));
}

// The world's block of `tile`, with its apron unless `apron` is false.
inline terrain::HeightBlock upsampledWorldBlock(const geo::TileId& tile, uint32_t verticesPerSide,
                                                bool apron = true) {
  const terrain::BlockGrid grid{tile, verticesPerSide};
  terrain::HeightBlock block;
  block.verticesPerSide = verticesPerSide;
  block.heights.resize(size_t{verticesPerSide} * verticesPerSide);
  for (uint32_t i = 0; i < verticesPerSide; ++i) {
    for (uint32_t j = 0; j < verticesPerSide; ++j) {
      block.heights[i * verticesPerSide + j] =
          upsampledWorldHeight(grid.longitudeDegrees(j), grid.latitudeDegrees(i));
    }
  }
  if (!apron) return block;
  block.apron.resize(terrain::apronSampleCount(verticesPerSide));
  const int last = static_cast<int>(verticesPerSide) - 1;
  for (int row = -terrain::kApronWidth; row <= last + terrain::kApronWidth; ++row) {
    for (int column = -terrain::kApronWidth; column <= last + terrain::kApronWidth; ++column) {
      if (row >= 0 && row <= last && column >= 0 && column <= last) continue;
      const terrain::BlockGrid::Vertex v = grid.wrappedVertex(row, column);
      block.apron[terrain::apronIndex(row, column, verticesPerSide)] =
          upsampledWorldHeight(v.longitudeDegrees, v.latitudeDegrees);
    }
  }
  return block;
}

}  // namespace globe::testing
