// The tiler's inputs: opened rasters in priority order (finest first), with the finest pyramid
// level each one supports and the closed extent it covers.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "core/result.hpp"
#include "formats/pyramid_manifest.hpp"
#include "rasters/raster_source.hpp"
#include "tiling/edge_profile.hpp"

namespace globe::tiling {

struct TilerSource {
  // Open only while it is read: openSources closes it once it knows the grid (a run of thousands
  // of inputs must not hold thousands of descriptors); the conditioning opens it again
  // (openRaster), reads it whole and puts its conditioned copy here.
  std::unique_ptr<rasters::RasterSource> raster;
  geo::SampleGrid grid;
  std::string argument;    // the path as given on the command line
  std::string rasterPath;  // the file the raster reads (GTOPO30: the .DEM of a .HDR argument)
  std::string format;      // the raster's format name ("GTOPO30" or GDAL's driver)
  rasters::RasterOpenOptions openOptions;
  double stepDegrees = 0;  // the finer of the two steps
  uint32_t finestLevel = 0;
  formats::BoundsDegrees extent;  // closed: the cells' extent, longitude ignored when wrapping
  // Height shared by every vertex at an exact pole this source covers, so a pole is one point.
  std::optional<int16_t> northPoleHeight, southPoleHeight;
  // Set by the conditioning: the margin over which coarser sources outside this one bend to meet
  // its edge (0: no coarser source around).
  double bendMarginDegrees = 0;
  // Its no data is an explicit water code, not voids (GTOPO30's ocean mask; tiler.hpp).
  bool noDataIsWater = false;
  // Set by the conditioning where bendMarginDegrees is: the edges the ground outside bends to.
  std::shared_ptr<const EdgeProfiles> edges;
  formats::VerticalUnits verticalUnits;  // how the raster's values became metres (kept:
                                         // conditioning replaces `raster` with its own copy)

  bool covers(double longitudeDegrees, double latitudeDegrees) const;
  formats::SourceInfo info() const;
};

// Opens the source's raster again if it is closed; an error if it no longer has the grid it had.
Result<void> openRaster(TilerSource& source);

// Height of a pole vertex from the source's row nearest the pole: its highest land sample (sea
// next to land counts as 0 m there), or the shallowest water when the row has no land, so the
// one polar point is never below any of the samples around it.
Result<int16_t> polarRowHeight(const rasters::RasterSource& raster, int64_t row);

// Finest level whose vertex spacing is not coarser than the source's sample step.
uint32_t finestLevelForStep(double stepDegrees, uint32_t verticesPerSide);

struct SourceSetOptions {
  uint32_t verticesPerSide = 17;
  std::optional<uint32_t> maxLevel;      // caps every source's finest level
  formats::VerticalOverride vertical{};  // --z-units / --z-scale, for every input
  bool noDataIsSea = false;              // --no-data-is-sea: every input's no data is water
  bool allowImages = false;              // --force: a colour image's band 1 as heights
};

// GTOPO30 itself (a 30″ grid in GTOPO30's format) has no voids: its -9999 is the ocean mask, an
// explicit water code. Other rasters' no data is missing data.
bool noDataIsOceanMask(const rasters::RasterSource& raster);

// Refuses a raster whose valid (not no-data) samples cannot make one 2x2 cell: fewer than 4 (none
// at all included), or all in one row or one column. Reads rows only until it has seen enough.
// A raster whose no data is its water code passes whatever it holds (an all-ocean tile).
Result<void> checkValidSamples(const rasters::RasterSource& raster, bool noDataIsWater);

// Opens every input, reads what the plan needs and closes it again; sorted finest first (ties keep
// command-line order) so the finest source covering a point wins.
Result<std::vector<TilerSource>> openSources(const std::vector<std::string>& inputs,
                                             const SourceSetOptions& options);

}  // namespace globe::tiling
