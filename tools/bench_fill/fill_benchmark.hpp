// One tile of the fill benchmark: holes of each size class cut into the truth, filled
// by every method on the same holes, scored against the removed samples.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "conditioning/coarser_sources.hpp"
#include "conditioning/dem_grid.hpp"
#include "conditioning/void_fill.hpp"
#include "core/result.hpp"
#include "tools/bench_fill/fill_error.hpp"
#include "tools/bench_fill/gdal_fill.hpp"
#include "tools/bench_fill/hole_generator.hpp"

namespace globe::bench_fill {

struct FillMethod {
  enum class Kind { Globe, Gdal };
  std::string label;
  Kind kind = Kind::Globe;
  const conditioning::CoarserSources* coarser = nullptr;  // Globe: nullptr = interpolation only
  GdalFillOptions gdal;                                   // Gdal
  bool harmonicOnly = false;  // Globe: no minimum-curvature refinement (what it adds, measured)
};

struct HoleClass {
  double diameterSamples = 0;
  size_t holes = 0;  // wanted; fewer where the land has no room
};

struct MethodResult {
  std::string label;
  ErrorSummary error;
  double medianFillMilliseconds = 0;
  bool deterministic = true;  // every repeat gave the same samples
  BorderCheck border;
  conditioning::FillStats stats;  // Globe only
};

struct ClassResult {
  double diameterSamples = 0;
  size_t holesWanted = 0, holes = 0, samples = 0;
  std::vector<MethodResult> methods;  // empty when no hole fits
};

struct BenchOptions {
  int repeats = 3;
  HolePlacement placement;  // its seed is combined with each class's diameter
  conditioning::FillOptions fill;
};

Result<std::vector<ClassResult>> benchmarkTile(const conditioning::DemGrid& truth,
                                               const std::vector<FillMethod>& methods,
                                               const std::vector<HoleClass>& classes,
                                               const BenchOptions& options);

}  // namespace globe::bench_fill
