// CoarserSources answered from conditioned grids in memory (the tiler's coarser inputs, or a
// test's or benchmark's own coarse grid). Grids are given finest first: the first covering a
// point is "the next coarser source" there.
#pragma once

#include <optional>
#include <vector>

#include "conditioning/coarser_sources.hpp"
#include "conditioning/dem_grid.hpp"

namespace globe::conditioning {

// Whether the grid's cells (sample centre ± half a step) cover the point.
bool gridCovers(const DemGrid& grid, double longitudeDegrees, double latitudeDegrees);

// Surface height (water at 0 m) at a covered point, by the tiler's vertex rule
// (conditioning/vertex_sample.hpp); the grid's edge samples extend to the cells' edge.
double bilinearSurfaceMeters(const DemGrid& grid, double longitudeDegrees, double latitudeDegrees);

class GridCoarserSources final : public CoarserSources {
 public:
  explicit GridCoarserSources(std::vector<const DemGrid*> finestFirst)
      : grids_(std::move(finestFirst)) {}
  bool allowSea(double longitudeDegrees, double latitudeDegrees) const override;
  std::optional<double> heightMeters(double longitudeDegrees,
                                     double latitudeDegrees) const override;
  std::optional<int16_t> sample(double longitudeDegrees, double latitudeDegrees) const override;

 private:
  std::vector<const DemGrid*> grids_;
};

}  // namespace globe::conditioning
