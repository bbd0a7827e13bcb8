// Builds one pack of the pyramid: each tile's vertices come from its existing children (every
// other child vertex) and, where no child exists, from the sources directly.
#pragma once

#include <map>
#include <vector>

#include "geo/ellipsoid.hpp"
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
// Each tile's geometric error is how far its surface lies from its children's vertices, and at
// least its children's own errors (0 for a tile of the finest data), so it never decreases going
// up; and at least terrain::geometricErrorMeters of its level where its children hold both water
// and land: a coastline's shape is in its sea flags, which no height deviation measures. (The
// max, not the sum, of the levels' deviations: the sum bounds the distance to the finest data
// but doubled the error of rough tiles; tools/bench_render/bench_lod.sh measures the images.)
Result<io::Pack> buildPack(const io::PackId& id, const io::PackLayout& layout,
                           const TilingPlan& plan, const std::vector<TilerSource>& sources,
                           const std::map<io::PackId, io::Pack>& childPacks,
                           const geo::Ellipsoid& ellipsoid, PackBuildStats& stats);

}  // namespace globe::tiler
