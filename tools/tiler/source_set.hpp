// The tiler's inputs: opened rasters in priority order (finest first), with the finest pyramid
// level each one supports and the closed extent it covers.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "geo/result.hpp"
#include "io/pyramid_manifest.hpp"
#include "io/raster_source.hpp"

namespace globe::tiler {

struct TilerSource {
  std::unique_ptr<io::RasterSource> raster;
  io::SampleGrid grid;
  std::string argument;    // the path as given on the command line
  double stepDegrees = 0;  // the finer of the two steps
  uint32_t finestLevel = 0;
  io::BoundsDegrees extent;  // closed: the cells' extent, longitude ignored when wrapping
  // Height shared by every vertex at an exact pole this source covers, so a pole is one point.
  std::optional<int16_t> northPoleHeight, southPoleHeight;
  // Set by the conditioning: the margin over which this source is eased into coarser ones, inside
  // its edges, and coarser land outside it towards its edge (0: no coarser source around).
  double featherMarginDegrees = 0;

  bool covers(double longitudeDegrees, double latitudeDegrees) const;
  io::SourceInfo info() const;
};

// Height of a pole vertex from the source's row nearest the pole: its highest land sample (sea
// next to land counts as 0 m there), or the shallowest water when the row has no land, so the
// one polar point is never below any of the samples around it.
Result<int16_t> polarRowHeight(const io::RasterSource& raster, int64_t row);

// Finest level whose vertex spacing is not coarser than the source's sample step.
uint32_t finestLevelForStep(double stepDegrees, uint32_t verticesPerSide);

struct SourceSetOptions {
  uint32_t verticesPerSide = 17;
  std::optional<uint32_t> maxLevel;  // caps every source's finest level
};

// Opens every input; sorted finest first (ties keep command-line order) so the finest source
// covering a point wins.
Result<std::vector<TilerSource>> openSources(const std::vector<std::string>& inputs,
                                             const SourceSetOptions& options);

}  // namespace globe::tiler
