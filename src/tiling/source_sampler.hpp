// Samples the tiler's sources at vertex positions: the finest covering source wins, its 2×2
// samples turned into a vertex by conditioning/vertex_sample.hpp's rule; within a finer source's
// bend margin outside its rectangle, the surface bends to meet that source's edge
// (conditioning/footprint_bend.hpp). Caches source rows for one
// strip of tiles so a strip costs a few row reads per source, not one read per vertex.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "core/result.hpp"
#include "tiling/source_set.hpp"

namespace globe::tiling {

// How much a vertex outside a finer source takes that source's edge: 1 at its edge, easing
// (smoothstep) to 0 at its bend margin; 0 inside it.
double bendWeightOutside(const TilerSource& finer, double longitudeDegrees, double latitudeDegrees);

class SourceSampler {
 public:
  // Only sources whose finest level is at most maxFinestLevel take part: where a finer source
  // covers a point, the tiler takes that vertex from the finer level instead. The strip's
  // longitudes bound the row segments read.
  SourceSampler(const std::vector<TilerSource>& sources, uint32_t maxFinestLevel,
                double stripWestDegrees, double stripEastDegrees);

  // GTOPO30 height at the point (int16 metres, -9999 when no source covers it).
  Result<int16_t> sample(double longitudeDegrees, double latitudeDegrees);

  uint64_t rowReads() const { return rowReads_; }

 private:
  struct Candidate {
    const TilerSource* source;
    int64_t firstColumn;  // of the cached row segments, in [0, cols)
    int64_t columnCount;
    bool bendOnly = false;  // finer than this level: read only for the bend at its edge
  };
  struct CachedRow {
    std::vector<int16_t> samples;
  };

  Result<int16_t> sampleSource(const Candidate& candidate, double longitudeDegrees,
                               double latitudeDegrees);
  Result<const std::vector<int16_t>*> row(size_t candidateIndex, int64_t row);
  int16_t at(const Candidate& candidate, const std::vector<int16_t>& rowSamples,
             int64_t column) const;

  std::vector<Candidate> candidates_;
  std::vector<size_t> bendCandidates_;  // indices into candidates_
  std::map<std::pair<size_t, int64_t>, CachedRow> rows_;
  uint64_t rowReads_ = 0;
};

}  // namespace globe::tiling
