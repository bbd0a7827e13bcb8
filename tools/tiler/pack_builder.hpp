// Builds one pack of the pyramid: each tile's vertices come from its existing children (every
// other child vertex) and, where no child exists, from the sources directly.
#pragma once

#include <map>
#include <vector>

#include "geo/result.hpp"
#include "io/pack_format.hpp"
#include "tools/tiler/source_sampler.hpp"
#include "tools/tiler/source_set.hpp"
#include "tools/tiler/tiling_plan.hpp"

namespace globe::tiler {

struct PackBuildStats {
  uint64_t tiles = 0;
  uint64_t sampledVertices = 0;    // read from sources
  uint64_t inheritedVertices = 0;  // taken from children
  uint64_t sourceRowReads = 0;
};

// childPacks: the finished packs of the next finer level under this pack (absent ones omitted).
Result<io::Pack> buildPack(const io::PackId& id, const io::PackLayout& layout,
                           const TilingPlan& plan, const std::vector<TilerSource>& sources,
                           const std::map<io::PackId, io::Pack>& childPacks, PackBuildStats& stats);

}  // namespace globe::tiler
