// Sea, void or outside the footprint, per sample, from the evidence. Sea only where something
// says sea:
//  - a measured sample at or below 0 m (SRTM writes the sea as 0 m, ETOPO as negative depths)
//    that every coarser source covering it allows as sea, connected (8-neighbours) through such
//    samples to open water: the grid's border, water the coarser sources say is there, or an
//    enclosed basin large and deep enough to be a sea (the Black Sea in a 20′ grid: at least
//    kSeaBasinMinimumAreaKm2 reaching kSeaBasinMinimumDepthMeters);
//  - a no-data sample where the coarser sources' surface (interpolated) is water;
//  - every no-data sample of a source whose no data is an explicit water code (GTOPO30's ocean
//    mask: the product has no voids, its -9999 is the ocean).
// Otherwise no data is never sea by connectivity alone. No data reaching the grid's border through
// no data along a long stretch of it, or covering much of the grid (reprojection wedges, a blanked
// half, the corners of a clipped image), lies outside the source's footprint: where a coarser
// source covers it, that source shows through there (Outside). A region meeting the border only
// briefly is a hole the grid's edge happens to cut (SRTM's voids cross its 1° tiles' edges) and
// is treated as any hole. Other no-data samples are voids (holes in the data, filled); other
// measured samples are land, below sea level included.
#pragma once

#include <cstdint>
#include <vector>

#include "conditioning/coarser_sources.hpp"
#include "conditioning/dem_grid.hpp"

namespace globe::conditioning {

inline constexpr double kSeaBasinMinimumAreaKm2 = 10000.0;
inline constexpr double kSeaBasinMinimumDepthMeters = -200.0;
// A no-data region reaching the border is outside the footprint when it meets the border along
// at least this fraction of the grid's shorter side, or covers at least this fraction of the grid.
inline constexpr double kOutsideBorderFraction = 0.25;
inline constexpr double kOutsideAreaFraction = 0.25;

enum class SampleClass : uint8_t { Land, Sea, Void, Outside };

struct SeaClassification {
  std::vector<SampleClass> classes;  // one per sample
  uint64_t seaSamples = 0;
  uint64_t voidSamples = 0;
  uint64_t outsideSamples = 0;  // no data outside the footprint, with a coarser source there
  uint64_t noDataSamples = 0;   // in the source as given
};

SeaClassification classifySea(const DemGrid& grid, const CoarserSources* coarser,
                              bool noDataIsWater = false);

}  // namespace globe::conditioning
