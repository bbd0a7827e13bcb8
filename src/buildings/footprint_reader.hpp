// Building footprints from any vector file OGR opens (GeoJSON, Shapefile, GeoPackage, KML, ...),
// in any CRS OGR can turn into longitude/latitude: every polygon (each part of a multi-polygon a
// footprint of its own) with its height (building_height.hpp). What cannot be a building is
// skipped, counted and named in a warning, never silently: footprints without a height, absurd
// heights, vertices that are not finite or not on the globe, rings too large to be a building.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "buildings/footprint.hpp"
#include "core/result.hpp"

namespace globe::buildings {

struct FootprintLimits {
  size_t maxFootprints = 2'000'000;  // in all files together: more is an error
  size_t maxVertices = 40'000'000;   // in all files together: more is an error
  size_t maxRingVertices = 2'000;    // a ring with more is skipped (roofs are O(n²))
  double maxExtentDegrees = 0.05;    // about 5 km: a footprint wider or taller is skipped
  size_t maxWarnings = 50;           // warnings kept; the others only counted
};

struct FootprintOptions {
  std::string heightAttribute;   // empty: `height`, then `building:levels`
  double levelHeightMeters = 3;  // a storey, for `building:levels`
  FootprintLimits limits;
};

struct FootprintSet {
  std::vector<Footprint> footprints;
  size_t withoutHeight = 0;  // features skipped: no height attribute of any kind
  size_t refused = 0;        // features skipped: a bad height or geometry (warned)
  size_t warningsDropped = 0;
  std::vector<std::string> warnings;
};

// Appends `path`'s footprints to `into`. Errors: a file OGR cannot open, one that holds no
// polygon at all, a CRS that does not turn into longitude/latitude, more than the limits allow;
// each names the file.
Result<void> readFootprints(const std::string& path, const FootprintOptions& options,
                            FootprintSet& into);

}  // namespace globe::buildings
