// Builds one pack of the pyramid: each tile's vertices come from its existing children (every
// other child vertex) and, where no child exists, from the sources directly.
#pragma once

#include <map>
#include <span>
#include <vector>

#include "core/result.hpp"
#include "formats/pack_format.hpp"
#include "geo/ellipsoid.hpp"
#include "tiling/sample_table.hpp"
#include "tiling/source_sampler.hpp"
#include "tiling/source_set.hpp"
#include "tiling/tiling_plan.hpp"

namespace globe::tiling {

struct PackBuildStats {
  uint64_t tiles = 0;
  uint64_t sampledVertices = 0;    // read from sources
  uint64_t inheritedVertices = 0;  // taken from children
  uint64_t sourceRowReads = 0;
};

// A tile's geometric error bounds how far its surface lies from its children's vertices, except
// for the largest few: the deviations that all but the largest kDeviationIgnoredFraction stay
// within, and at least kDeviationMaxFraction of the largest. On rough terrain the largest
// deviations are a few vertices on cliff edges, which change few pixels; bounding them made the
// selection refine canyons (Zion) a level further than the image needed. The fraction of the
// largest keeps a lone peak from being ignored: at the 2 px threshold it moves at most 5 px.
// tools/bench_render/bench_lod.sh measures the images (docs/performance/performance-lod.md).
inline constexpr double kDeviationIgnoredFraction = 0.03;
inline constexpr double kDeviationMaxFraction = 0.4;

// The geometric error of a set of vertex deviations in metres, by the rule above (reorders them);
// 0 for none.
double geometricErrorOfDeviations(std::span<double> deviationsMeters);

// childPacks: the finished packs of the next finer level under this pack (absent ones omitted).
// precomputed: heights the shards read (the merge); the rest are read from `sources`.
// Each tile's geometric error is that of its children's vertices from its surface, and at
// least its children's own errors (0 for a tile of the finest data), so it never decreases going
// up; and at least terrain::geometricErrorMeters of its level where its children hold both water
// and land: a coastline's shape is in its sea flags, which no height deviation measures. (The
// max, not the sum, of the levels' deviations: the sum bounds the distance to the finest data
// but doubled the error of rough tiles; tools/bench_render/bench_lod.sh measures the images.)
Result<formats::Pack> buildPack(const formats::PackId& id, const formats::PackLayout& layout,
                                const TilingPlan& plan, const std::vector<TilerSource>& sources,
                                const std::map<formats::PackId, formats::Pack>& childPacks,
                                const geo::Ellipsoid& ellipsoid, PackBuildStats& stats,
                                const PrecomputedSamples& precomputed = {});

}  // namespace globe::tiling
