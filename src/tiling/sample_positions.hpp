// The heights of a tile that come from the sources rather than from its children, and the
// samplers that read them, one set per row of tiles in a pack. The pack builder, the shards
// (which read them for the merge) and the merge all go through these, so a height is read at the
// same point from the same sources whoever reads it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/result.hpp"
#include "geo/tile_id.hpp"
#include "tiling/source_sampler.hpp"
#include "tiling/source_set.hpp"
#include "tiling/tiling_plan.hpp"

namespace globe::tiling {

struct SamplePosition {
  // A vertex row * n + column, or n * n + the apron index (terrain::apronIndex).
  uint32_t index = 0;
  double longitudeDegrees = 0, latitudeDegrees = 0;
  // A vertex takes the sources of its own level; the apron takes every source, as the finest
  // neighbouring tiles hold it, beyond a pole from the opposite meridians.
  enum class From : uint8_t { Vertex, Apron, OverThePole } from = From::Vertex;
};

// Index space of one tile's positions: n * n vertices, then the apron.
uint32_t positionsPerTile(uint32_t verticesPerSide);

// Every vertex no existing child fills, then the whole apron, in index order.
std::vector<SamplePosition> sourcePositions(const TilingPlan& plan, const geo::TileId& tile,
                                            uint32_t verticesPerSide);

// The samplers of one row of tiles of a pack (west to east, as TilingPlan::tilesInPack lists them).
class StripSamplers {
 public:
  StripSamplers(const std::vector<TilerSource>& sources, const TilingPlan& plan,
                const geo::TileId& westTile, const geo::TileId& eastTile, uint32_t verticesPerSide);
  Result<int16_t> sample(const SamplePosition& position);
  uint64_t rowReads() const { return vertices_.rowReads(); }

 private:
  SourceSampler vertices_;
  SourceSampler apron_;
  std::optional<SourceSampler> overThePole_;
};

}  // namespace globe::tiling
