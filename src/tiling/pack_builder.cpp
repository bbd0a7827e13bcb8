#include "tiling/pack_builder.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/screen_space_error.hpp"

namespace globe::tiling {
namespace {

// Copies the child's even vertices into its quadrant of the parent; marks them as filled.
void inheritFromChild(const formats::Pack& childPack, const geo::TileId& child, size_t quadrant,
                      std::span<int16_t> parent, std::vector<bool>& filled, uint32_t n) {
  const uint32_t half = (n - 1) / 2;
  const uint32_t rowOffset = quadrant >= 2 ? half : 0;
  const uint32_t columnOffset = quadrant % 2 == 1 ? half : 0;
  std::span<const int16_t> source =
      childPack.block(formats::slotOf(child, childPack.layout.tilesPerSide));
  for (uint32_t i = 0; i <= half; ++i) {
    for (uint32_t j = 0; j <= half; ++j) {
      const size_t target = size_t{rowOffset + i} * n + columnOffset + j;
      parent[target] = source[size_t{2 * i} * n + 2 * j];
      filled[target] = true;
    }
  }
}

// How far the child's vertices lie from the parent's surface over the child's quadrant, in
// metres (pack_builder.hpp: all but the largest kDeviationIgnoredFraction of them, and at least
// kDeviationMaxFraction of the largest). Per vertex, the larger deviation under either sea
// surface; the parent's vertices there are the child's even vertices, drawn as two triangles per
// cell split along the north-west to south-east diagonal (terrain/tile_mesh.hpp's rule).
double deviationFromParent(std::span<const int16_t> child, uint32_t n) {
  std::vector<double> deviations;
  deviations.reserve(size_t{n} * n);
  for (uint32_t i = 0; i < n; ++i) {
    for (uint32_t j = 0; j < n; ++j) {
      if (i % 2 == 0 && j % 2 == 0) continue;
      double deviation = 0;
      for (const terrain::SeaSurface sea :
           {terrain::SeaSurface::Water, terrain::SeaSurface::SeaFloor}) {
        auto h = [&](uint32_t r, uint32_t c) {
          return terrain::surfaceHeightMeters(child[size_t{r} * n + c], sea);
        };
        // The parent cell's north-west corner; an even row or column lies on the cell's edge,
        // which may be the block's last row or column, so only the corners it needs are read.
        const uint32_t i0 = i & ~1u, j0 = j & ~1u;
        const double a = h(i0, j0);
        double surface = 0;
        if (i == i0) {
          surface = (a + h(i0, j0 + 2)) / 2;  // middle of a west-east edge
        } else if (j == j0) {
          surface = (a + h(i0 + 2, j0)) / 2;  // middle of a north-south edge
        } else {
          surface = (a + h(i0 + 2, j0 + 2)) / 2;  // middle of the north-west to south-east diagonal
        }
        deviation = std::max(deviation, std::abs(h(i, j) - surface));
      }
      deviations.push_back(deviation);
    }
  }
  return geometricErrorOfDeviations(deviations);
}

}  // namespace

double geometricErrorOfDeviations(std::span<double> deviationsMeters) {
  if (deviationsMeters.empty()) return 0.0;
  const auto ignored =
      static_cast<size_t>(kDeviationIgnoredFraction * static_cast<double>(deviationsMeters.size()));
  // Descending: position `ignored` is the largest deviation left once the ignored are dropped.
  const auto kept = deviationsMeters.begin() + static_cast<std::ptrdiff_t>(ignored);
  std::nth_element(deviationsMeters.begin(), kept, deviationsMeters.end(), std::greater<>());
  const double largest =
      *std::max_element(deviationsMeters.begin(),
                        deviationsMeters.begin() + static_cast<std::ptrdiff_t>(ignored) + 1);
  return std::max(*kept, kDeviationMaxFraction * largest);
}

Result<formats::Pack> buildPack(const formats::PackId& id, const formats::PackLayout& layout,
                                const TilingPlan& plan, const std::vector<TilerSource>& sources,
                                const std::map<formats::PackId, formats::Pack>& childPacks,
                                const geo::Ellipsoid& ellipsoid, PackBuildStats& stats,
                                const PrecomputedSamples& precomputed) {
  const uint32_t n = layout.verticesPerSide;
  formats::Pack pack = formats::Pack::unset(id, layout);  // every present tile is set whole
  const std::vector<geo::TileId> tiles = plan.tilesInPack(id);

  // One strip per row of tiles: the samplers cache the source rows the strip needs.
  for (size_t begin = 0; begin < tiles.size();) {
    size_t end = begin;
    while (end < tiles.size() && tiles[end].y == tiles[begin].y) ++end;
    StripSamplers samplers(sources, plan, tiles[begin], tiles[end - 1], n);
    for (size_t t = begin; t < end; ++t) {
      const geo::TileId& tile = tiles[t];
      const size_t slot = formats::slotOf(tile, layout.tilesPerSide);
      std::span<int16_t> block = pack.block(slot);
      std::vector<bool> filled(block.size(), false);
      formats::PackEntry& entry = pack.entries[slot];
      entry.blockOffset = 1;  // present; encodePack assigns the real offset
      std::optional<terrain::HeightRange> childrenRange;
      double geometricErrorMeters = 0;   // 0 for a tile of the finest data
      bool water = false, land = false;  // among the children's vertices

      const auto children = tile.children();
      for (size_t q = 0; q < children.size(); ++q) {
        if (!plan.exists(children[q])) continue;
        auto found = childPacks.find(formats::packOf(children[q], layout.tilesPerSide));
        if (found == childPacks.end()) {
          return makeError("internal: the pack of child tile " + std::to_string(children[q].level) +
                           "/" + std::to_string(children[q].x) + "/" +
                           std::to_string(children[q].y) + " was not built");
        }
        inheritFromChild(found->second, children[q], q, block, filled, n);
        const size_t childSlot = formats::slotOf(children[q], layout.tilesPerSide);
        const auto& childEntry = found->second.entries[childSlot];
        // The parent stands for everything under the child: never less than the child's error.
        const double childError = std::isfinite(childEntry.geometricErrorMeters)
                                      ? std::max(0.0, double{childEntry.geometricErrorMeters})
                                      : 0.0;
        const std::span<const int16_t> childBlock = found->second.block(childSlot);
        geometricErrorMeters =
            std::max({geometricErrorMeters, deviationFromParent(childBlock, n), childError});
        for (const int16_t sample : childBlock) {
          (terrain::isWater(sample) ? water : land) = true;
        }
        if (!childrenRange) childrenRange = childEntry.subtreeRange;
        childrenRange->include(childEntry.subtreeRange);
      }

      stats.inheritedVertices +=
          static_cast<uint64_t>(std::count(filled.begin(), filled.end(), true));
      std::span<int16_t> apron = pack.apron(slot);
      for (const SamplePosition& position : sourcePositions(plan, tile, n)) {
        std::optional<int16_t> height;
        if (precomputed.table != nullptr) height = precomputed.table->find(slot, position.index);
        if (!height && precomputed.mustHold && precomputed.mustHold(position)) {
          return makeError("tile " + std::to_string(tile.level) + "/" + std::to_string(tile.x) +
                           "/" + std::to_string(tile.y) +
                           ": a height the shards read is missing (a shard's samples lost?)");
        }
        if (!height) {
          auto sampled = samplers.sample(position);
          if (!sampled) return Error{sampled.error()};
          height = *sampled;
          if (position.index < n * n) ++stats.sampledVertices;
        }
        if (position.index < n * n) {
          block[position.index] = *height;
        } else {
          apron[position.index - n * n] = *height;
        }
      }
      if (water && land) {
        geometricErrorMeters =
            std::max(geometricErrorMeters, terrain::geometricErrorMeters(tile.level, n, ellipsoid));
      }
      // Rounded up so that the float never understates the error.
      entry.geometricErrorMeters = std::nextafter(static_cast<float>(geometricErrorMeters),
                                                  std::numeric_limits<float>::infinity());
      if (geometricErrorMeters == 0) entry.geometricErrorMeters = 0.0f;
      const terrain::HeightBlock heights{n, std::vector<int16_t>(block.begin(), block.end())};
      entry.vertexRange = terrain::surfaceHeightRange(heights);
      entry.subtreeRange = entry.vertexRange;
      if (childrenRange) entry.subtreeRange.include(*childrenRange);
      ++stats.tiles;
    }
    stats.sourceRowReads += samplers.rowReads();
    begin = end;
  }
  return pack;
}

}  // namespace globe::tiling
