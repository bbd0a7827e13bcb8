#include "tools/tiler/pack_builder.hpp"

#include <algorithm>

#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"

namespace globe::tiler {
namespace {

// Copies the child's even vertices into its quadrant of the parent; marks them as filled.
void inheritFromChild(const io::Pack& childPack, const geo::TileId& child, size_t quadrant,
                      std::span<int16_t> parent, std::vector<bool>& filled, uint32_t n) {
  const uint32_t half = (n - 1) / 2;
  const uint32_t rowOffset = quadrant >= 2 ? half : 0;
  const uint32_t columnOffset = quadrant % 2 == 1 ? half : 0;
  std::span<const int16_t> source =
      childPack.block(io::slotOf(child, childPack.layout.tilesPerSide));
  for (uint32_t i = 0; i <= half; ++i) {
    for (uint32_t j = 0; j <= half; ++j) {
      const size_t target = size_t{rowOffset + i} * n + columnOffset + j;
      parent[target] = source[size_t{2 * i} * n + 2 * j];
      filled[target] = true;
    }
  }
}

}  // namespace

Result<io::Pack> buildPack(const io::PackId& id, const io::PackLayout& layout,
                           const TilingPlan& plan, const std::vector<TilerSource>& sources,
                           const std::map<io::PackId, io::Pack>& childPacks,
                           PackBuildStats& stats) {
  const uint32_t n = layout.verticesPerSide;
  io::Pack pack = io::Pack::empty(id, layout);
  const std::vector<geo::TileId> tiles = plan.tilesInPack(id);

  // One strip per row of tiles: the sampler caches the source rows the strip needs.
  for (size_t begin = 0; begin < tiles.size();) {
    size_t end = begin;
    while (end < tiles.size() && tiles[end].y == tiles[begin].y) ++end;
    const terrain::BlockGrid westTile{tiles[begin], n};
    const terrain::BlockGrid eastTile{tiles[end - 1], n};
    SourceSampler sampler(sources, id.level, westTile.longitudeDegrees(0),
                          eastTile.longitudeDegrees(n - 1));

    for (size_t t = begin; t < end; ++t) {
      const geo::TileId& tile = tiles[t];
      const size_t slot = io::slotOf(tile, layout.tilesPerSide);
      std::span<int16_t> block = pack.block(slot);
      std::vector<bool> filled(block.size(), false);
      io::PackEntry& entry = pack.entries[slot];
      entry.blockOffset = 1;  // present; encodePack assigns the real offset
      std::optional<terrain::HeightRange> childrenRange;

      const auto children = tile.children();
      for (size_t q = 0; q < children.size(); ++q) {
        if (!plan.exists(children[q])) continue;
        auto found = childPacks.find(io::packOf(children[q], layout.tilesPerSide));
        if (found == childPacks.end()) {
          return makeError("internal: the pack of child tile " + std::to_string(children[q].level) +
                           "/" + std::to_string(children[q].x) + "/" +
                           std::to_string(children[q].y) + " was not built");
        }
        inheritFromChild(found->second, children[q], q, block, filled, n);
        const auto& childEntry =
            found->second.entries[io::slotOf(children[q], layout.tilesPerSide)];
        if (!childrenRange) childrenRange = childEntry.subtreeRange;
        childrenRange->include(childEntry.subtreeRange);
      }

      const terrain::BlockGrid grid{tile, n};
      for (uint32_t i = 0; i < n; ++i) {
        const double latitude = grid.latitudeDegrees(i);
        for (uint32_t j = 0; j < n; ++j) {
          const size_t k = size_t{i} * n + j;
          if (filled[k]) {
            ++stats.inheritedVertices;
            continue;
          }
          auto height = sampler.sample(grid.longitudeDegrees(j), latitude);
          if (!height) return Error{height.error()};
          block[k] = *height;
          ++stats.sampledVertices;
        }
      }
      const terrain::HeightBlock heights{n, std::vector<int16_t>(block.begin(), block.end())};
      entry.vertexRange = terrain::surfaceHeightRange(heights);
      entry.subtreeRange = entry.vertexRange;
      if (childrenRange) entry.subtreeRange.include(*childrenRange);
      ++stats.tiles;
    }
    stats.sourceRowReads += sampler.rowReads();
    begin = end;
  }
  return pack;
}

}  // namespace globe::tiler
