#include "conditioning/void_fill.hpp"

#include <algorithm>
#include <optional>

#include "conditioning/harmonic_fill.hpp"
#include "conditioning/minimum_curvature.hpp"
#include "conditioning/vertex_sample.hpp"
#include "terrain/height_block.hpp"

namespace globe::conditioning {
namespace {

// One 4-connected void region: its samples in scan order.
std::vector<size_t> collectRegion(const DemGrid& grid, const std::vector<uint8_t>& isVoid,
                                  std::vector<uint8_t>& seen, size_t start) {
  std::vector<size_t> region{start};
  seen[start] = 1;
  for (size_t k = 0; k < region.size(); ++k) {
    const auto row = static_cast<int64_t>(region[k] / static_cast<size_t>(grid.cols));
    const auto column = static_cast<int64_t>(region[k] % static_cast<size_t>(grid.cols));
    forEachNeighbour(grid, row, column, [&](int64_t r, int64_t c) {
      const size_t i = grid.index(r, c);
      if (isVoid[i] != 0 && seen[i] == 0) {
        seen[i] = 1;
        region.push_back(i);
      }
    });
  }
  std::sort(region.begin(), region.end());
  return region;
}

}  // namespace

FillStats fillVoids(DemGrid& grid, const std::vector<uint8_t>& isVoid,
                    const CoarserSources* coarser, const FillOptions& options) {
  FillStats stats;
  std::vector<uint8_t> seen(grid.samples.size(), 0);
  for (size_t start = 0; start < grid.samples.size(); ++start) {
    if (isVoid[start] == 0 || seen[start] != 0) continue;
    const std::vector<size_t> region = collectRegion(grid, isVoid, seen, start);
    ++stats.voids;

    // The coarser surface under every void sample, when a coarser source covers all of them.
    std::optional<std::vector<double>> coarse;
    if (coarser != nullptr) {
      coarse.emplace(region.size());
      for (size_t k = 0; k < region.size() && coarse; ++k) {
        const auto row = static_cast<int64_t>(region[k] / static_cast<size_t>(grid.cols));
        const auto column = static_cast<int64_t>(region[k] % static_cast<size_t>(grid.cols));
        const auto h =
            coarser->heightMeters(grid.longitudeDegrees(column), grid.latitudeDegrees(row));
        if (h) {
          (*coarse)[k] = *h;
        } else {
          coarse.reset();
        }
      }
    }
    const bool large = static_cast<int64_t>(region.size()) > options.smallVoidMaxSamples;
    const bool fromCoarser = coarse.has_value() && large;

    // Border values: the surface itself, or (delta surface) its difference to the coarser one.
    auto borderValue = [&](int64_t row, int64_t column) -> double {
      const double fine = terrain::surfaceHeightMeters(grid.at(row, column));
      if (!fromCoarser) return fine;
      const auto h =
          coarser->heightMeters(grid.longitudeDegrees(column), grid.latitudeDegrees(row));
      return h ? fine - *h : 0.0;
    };
    std::optional<std::vector<double>> solved = solveHarmonic(grid, isVoid, region, borderValue);
    if (solved && static_cast<int64_t>(region.size()) <= options.minimumCurvatureMaxSamples) {
      solved = solveMinimumCurvature(grid, isVoid, region, borderValue, std::move(*solved),
                                     options.tension);
    }
    bool usedCoarser = fromCoarser;
    if (!solved) {
      // No border at all (the whole grid is void): the coarser surface as it is, if any.
      if (!coarse) {
        stats.unfilledSamples += region.size();
        continue;
      }
      solved.emplace(region.size(), 0.0);
      usedCoarser = true;
    }
    for (size_t k = 0; k < region.size(); ++k) {
      const double height = (*solved)[k] + (usedCoarser ? (*coarse)[k] : 0.0);
      grid.samples[region[k]] = landSample(height);
    }
    (usedCoarser ? stats.fromCoarserSamples : stats.interpolatedSamples) += region.size();
  }
  return stats;
}

}  // namespace globe::conditioning
