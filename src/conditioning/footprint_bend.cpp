#include "conditioning/footprint_bend.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "conditioning/harmonic_fill.hpp"
#include "conditioning/vertex_sample.hpp"
#include "terrain/height_block.hpp"

namespace globe::conditioning {
namespace {

// Δ to a centimetre: the heights are whole metres.
constexpr double kBendToleranceMeters = 0.01;

// Distance in degrees from every sample to the nearest footprint sample (0 on it), by vector
// propagation over the 8 neighbours in four sweeps (Danielsson's 8SSEDT).
std::vector<double> distanceToFootprint(const DemGrid& grid, const std::vector<uint8_t>& outside) {
  constexpr size_t kNoSite = std::numeric_limits<size_t>::max();
  const size_t count = grid.samples.size();
  std::vector<size_t> site(count, kNoSite);
  std::vector<double> distance2(count, std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < count; ++i) {
    if (outside[i] == 0) site[i] = i, distance2[i] = 0;
  }
  const auto cols = static_cast<size_t>(grid.cols);
  auto offer = [&](int64_t row, int64_t column, int64_t fromRow, int64_t fromColumn) {
    if (fromRow < 0 || fromRow >= grid.rows || fromColumn < 0 || fromColumn >= grid.cols) return;
    const size_t candidate = site[grid.index(fromRow, fromColumn)];
    if (candidate == kNoSite) return;
    const size_t i = grid.index(row, column);
    const double dx = static_cast<double>(column - static_cast<int64_t>(candidate % cols)) *
                      grid.columnStepDegrees;
    const double dy =
        static_cast<double>(row - static_cast<int64_t>(candidate / cols)) * grid.rowStepDegrees;
    const double d2 = dx * dx + dy * dy;
    if (d2 < distance2[i]) distance2[i] = d2, site[i] = candidate;
  };
  for (int64_t r = 0; r < grid.rows; ++r) {
    for (int64_t c = 0; c < grid.cols; ++c) {
      offer(r, c, r - 1, c - 1), offer(r, c, r - 1, c), offer(r, c, r - 1, c + 1);
      offer(r, c, r, c - 1);
    }
    for (int64_t c = grid.cols - 1; c >= 0; --c) offer(r, c, r, c + 1);
  }
  for (int64_t r = grid.rows - 1; r >= 0; --r) {
    for (int64_t c = grid.cols - 1; c >= 0; --c) {
      offer(r, c, r + 1, c + 1), offer(r, c, r + 1, c), offer(r, c, r + 1, c - 1);
      offer(r, c, r, c + 1);
    }
    for (int64_t c = 0; c < grid.cols; ++c) offer(r, c, r, c - 1);
  }
  for (double& d : distance2) d = std::sqrt(d);
  return distance2;
}

// 3t² − 2t³ of t clamped to [0, 1].
double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace

double bendWeight(double distanceDegrees, double marginDegrees) {
  if (!(marginDegrees > 0) || !(distanceDegrees < marginDegrees)) return 0.0;
  return 1.0 - smoothstep(distanceDegrees / marginDegrees);
}

int16_t bentSample(int16_t coarseHere, double deltaMeters) {
  if (deltaMeters == 0.0) return coarseHere;
  const double hereMeters = terrain::seaFloorMeters(coarseHere);
  const double heightMeters = hereMeters + deltaMeters;
  if (terrain::isWater(coarseHere)) {
    return heightMeters <= 0.0 ? terrain::encodeWater(heightMeters) : landSample(heightMeters);
  }
  return landSample(std::max(heightMeters, std::min(0.0, hereMeters)));
}

uint64_t bendCoarserToFootprint(DemGrid& grid, const std::vector<uint8_t>& outside,
                                const CoarserSources& coarser, double marginDegrees) {
  const size_t count = grid.samples.size();
  const auto cols = static_cast<size_t>(grid.cols);
  auto coarseAt = [&](size_t i) {
    return coarser.sample(grid.longitudeDegrees(static_cast<int64_t>(i % cols)),
                          grid.latitudeDegrees(static_cast<int64_t>(i / cols)));
  };
  // Δ is solved over the outside samples within the margin; beyond it Δ = 0, and on the
  // footprint's samples next to them it is the finer height's difference to the coarser one.
  const std::vector<double> distance = distanceToFootprint(grid, outside);
  std::vector<uint8_t> solved(count, 0);
  for (size_t i = 0; i < count; ++i) {
    solved[i] = outside[i] != 0 && distance[i] < marginDegrees ? 1 : 0;
  }
  auto borderDelta = [&](int64_t row, int64_t column) -> double {
    const size_t i = grid.index(row, column);
    if (outside[i] != 0) return 0.0;  // beyond the margin
    const auto coarse = coarseAt(i);
    if (!coarse) return 0.0;
    return terrain::seaFloorMeters(grid.samples[i]) - terrain::seaFloorMeters(*coarse);
  };
  std::vector<double> delta(count, 0.0);
  std::vector<uint8_t> seen(count, 0);
  for (size_t start = 0; start < count; ++start) {
    if (solved[start] == 0 || seen[start] != 0) continue;
    std::vector<size_t> region{start};
    seen[start] = 1;
    for (size_t k = 0; k < region.size(); ++k) {
      forEachNeighbour(grid, static_cast<int64_t>(region[k] / cols),
                       static_cast<int64_t>(region[k] % cols), [&](int64_t r, int64_t c) {
                         const size_t j = grid.index(r, c);
                         if (solved[j] != 0 && seen[j] == 0) seen[j] = 1, region.push_back(j);
                       });
    }
    std::sort(region.begin(), region.end());
    // Across, the region is at most twice its farthest sample's distance from the footprint.
    double farthestDegrees = 0;
    for (size_t i : region) farthestDegrees = std::max(farthestDegrees, distance[i]);
    const double acrossSamples =
        2 * farthestDegrees / std::min(grid.columnStepDegrees, grid.rowStepDegrees) + 1;
    const auto values =
        solveHarmonic(grid, solved, region, borderDelta, kBendToleranceMeters, acrossSamples);
    if (!values) continue;  // nothing to meet: the coarser surface as it is
    // Shaped so Δ leaves the edge level and eases into the margin (in one dimension the harmonic
    // Δ is Δ₀(1 − t), t = d / margin; times (1 − t)(1 + 2t) it is Δ₀(1 − smoothstep(t))).
    for (size_t k = 0; k < region.size(); ++k) {
      const double t = std::min(distance[region[k]] / marginDegrees, 1.0);
      delta[region[k]] = (*values)[k] * (1 - t) * (1 + 2 * t);
    }
  }
  uint64_t written = 0;
  for (size_t i = 0; i < count; ++i) {
    if (outside[i] == 0) continue;
    const auto coarse = coarseAt(i);
    if (!coarse) continue;  // the classification marks only covered samples
    grid.samples[i] = bentSample(*coarse, delta[i]);
    ++written;
  }
  return written;
}

}  // namespace globe::conditioning
