// Sea or void, per sample, from the evidence. A sample may be sea when it is no data or at most
// 0 m (SRTM writes the sea as 0 m, GTOPO30 as no data, ETOPO as negative depths) and every
// coarser source covering it allows sea there. It is sea when it is connected (8-neighbours)
// through such samples to open sea: the grid's border, or an enclosed basin large and deep
// enough to be a sea (the Black Sea in a 20′ grid: at least kSeaBasinMinimumAreaKm2 reaching
// kSeaBasinMinimumDepthMeters). Other no-data samples are voids (holes in land); other measured
// samples are land, below sea level included.
#pragma once

#include <cstdint>
#include <vector>

#include "dem/coarser_sources.hpp"
#include "dem/dem_grid.hpp"

namespace globe::dem {

inline constexpr double kSeaBasinMinimumAreaKm2 = 10000.0;
inline constexpr double kSeaBasinMinimumDepthMeters = -200.0;

enum class SampleClass : uint8_t { Land, Sea, Void };

struct SeaClassification {
  std::vector<SampleClass> classes;  // one per sample
  uint64_t seaSamples = 0;
  uint64_t voidSamples = 0;
  uint64_t noDataSamples = 0;  // in the source as given
};

SeaClassification classifySea(const DemGrid& grid, const CoarserSources* coarser);

}  // namespace globe::dem
