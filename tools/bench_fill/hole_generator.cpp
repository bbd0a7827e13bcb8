// Blob shapes and their placement on land, driven by one 64-bit Mersenne Twister per call.
#include "tools/bench_fill/hole_generator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace globe::bench_fill {
namespace {

// Uniform in [0, 1) from the top 53 bits: identical on every standard library.
double unitInterval(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Uniform integer in [low, high] (high >= low); the modulo bias is irrelevant here.
int64_t uniformInteger(std::mt19937_64& rng, int64_t low, int64_t high) {
  const auto span = static_cast<uint64_t>(high - low) + 1;
  return low + static_cast<int64_t>(rng() % span);
}

// Keeps the offsets 4-connected to (0, 0) through the set.
std::vector<Offset> connectedToOrigin(const std::vector<Offset>& offsets, int64_t reach) {
  const int64_t side = 2 * reach + 1;
  std::vector<uint8_t> inside(static_cast<size_t>(side * side), 0);
  auto cell = [&](int64_t row, int64_t column) {
    return static_cast<size_t>((row + reach) * side + (column + reach));
  };
  for (const Offset& o : offsets) inside[cell(o.row, o.column)] = 1;
  std::vector<Offset> kept;
  std::vector<Offset> stack{{0, 0}};
  inside[cell(0, 0)] = 2;
  while (!stack.empty()) {
    const Offset o = stack.back();
    stack.pop_back();
    kept.push_back(o);
    const Offset next[] = {
        {o.row - 1, o.column}, {o.row + 1, o.column}, {o.row, o.column - 1}, {o.row, o.column + 1}};
    for (const Offset& n : next) {
      if (std::abs(n.row) > reach || std::abs(n.column) > reach) continue;
      uint8_t& state = inside[cell(n.row, n.column)];
      if (state != 1) continue;
      state = 2;
      stack.push_back(n);
    }
  }
  std::sort(kept.begin(), kept.end(), [](const Offset& a, const Offset& b) {
    return a.row != b.row ? a.row < b.row : a.column < b.column;
  });
  return kept;
}

// Marks every sample within `gap` (Chebyshev) of the hole as blocked for later holes.
void block(const conditioning::DemGrid& grid, const Hole& hole, int64_t gap,
           std::vector<uint8_t>& blocked) {
  for (size_t index : hole.samples) {
    const auto row = static_cast<int64_t>(index) / grid.cols;
    const auto column = static_cast<int64_t>(index) % grid.cols;
    for (int64_t r = std::max<int64_t>(0, row - gap); r <= std::min(grid.rows - 1, row + gap);
         ++r) {
      for (int64_t c = std::max<int64_t>(0, column - gap);
           c <= std::min(grid.cols - 1, column + gap); ++c) {
        blocked[grid.index(r, c)] = 1;
      }
    }
  }
}

// The radius of a blob varies within (1 ± kMaxWobble) × half its diameter.
constexpr double kHarmonicAmplitude = 0.1;  // at most, each of three harmonics
constexpr double kMaxWobble = 3 * kHarmonicAmplitude;

// Half the side of the square that holds every blob of this diameter.
int64_t blobReach(double diameterSamples) {
  return static_cast<int64_t>(std::ceil(0.5 * diameterSamples * (1 + kMaxWobble))) + 1;
}

// Chessboard distance from each sample to the nearest sample that is not land or lies beyond
// the grid (0 on such samples): two chamfer passes over the 8-neighbourhood.
std::vector<int64_t> distanceToNonLand(const conditioning::DemGrid& grid) {
  std::vector<int64_t> distance(grid.samples.size());
  auto at = [&](int64_t row, int64_t column) -> int64_t {
    if (row < 0 || column < 0 || row >= grid.rows || column >= grid.cols) return 0;
    return distance[grid.index(row, column)];
  };
  for (int64_t row = 0; row < grid.rows; ++row) {
    for (int64_t column = 0; column < grid.cols; ++column) {
      const size_t i = grid.index(row, column);
      distance[i] = isLand(grid.samples[i])
                        ? 1 + std::min({at(row - 1, column - 1), at(row - 1, column),
                                        at(row - 1, column + 1), at(row, column - 1)})
                        : 0;
    }
  }
  for (int64_t row = grid.rows - 1; row >= 0; --row) {
    for (int64_t column = grid.cols - 1; column >= 0; --column) {
      int64_t& d = distance[grid.index(row, column)];
      d = std::min(d, 1 + std::min({at(row + 1, column + 1), at(row + 1, column),
                                    at(row + 1, column - 1), at(row, column + 1)}));
    }
  }
  return distance;
}

}  // namespace

std::vector<Offset> blobOffsets(double diameterSamples, uint64_t seed) {
  std::mt19937_64 rng(seed);
  constexpr int kHarmonics[] = {2, 3, 5};
  double amplitude[3], phaseRadians[3];
  for (size_t k = 0; k < 3; ++k) {
    amplitude[k] = kHarmonicAmplitude * unitInterval(rng);
    phaseRadians[k] = 2 * std::numbers::pi * unitInterval(rng);
  }
  const double radius = 0.5 * diameterSamples;
  const int64_t reach = blobReach(diameterSamples);
  std::vector<Offset> offsets;
  for (int64_t row = -reach; row <= reach; ++row) {
    for (int64_t column = -reach; column <= reach; ++column) {
      const double angleRadians = std::atan2(static_cast<double>(row), static_cast<double>(column));
      double wobble = 1;
      for (size_t k = 0; k < 3; ++k) {
        wobble += amplitude[k] * std::cos(kHarmonics[k] * angleRadians + phaseRadians[k]);
      }
      if (std::hypot(static_cast<double>(row), static_cast<double>(column)) <= radius * wobble) {
        offsets.push_back({row, column});
      }
    }
  }
  return connectedToOrigin(offsets, reach);
}

std::vector<Hole> placeHoles(const conditioning::DemGrid& grid, double diameterSamples,
                             size_t count, const HolePlacement& placement) {
  std::mt19937_64 rng(placement.seed);
  std::vector<uint8_t> blocked(grid.samples.size(), 0);
  std::vector<Hole> holes;
  // Every blob holds the disc of 0.7 × its radius: a centre with non-land within that disc
  // (chessboard distance d puts it within d·√2) can be rejected before the blob is drawn.
  const std::vector<int64_t> landDistance = distanceToNonLand(grid);
  const double innerRadius = 0.5 * diameterSamples * (1 - kMaxWobble);
  const auto attempts = static_cast<int64_t>(count) * placement.attemptsPerHole;
  for (int64_t attempt = 0; attempt < attempts && holes.size() < count; ++attempt) {
    // A margin of at least 1 keeps the 8-neighbour ring of every hole sample inside the grid.
    const int64_t reach =
        blobReach(diameterSamples) + std::max<int64_t>(1, placement.edgeMarginSamples);
    if (2 * reach >= grid.rows || 2 * reach >= grid.cols) break;
    Hole hole;
    hole.centreRow = uniformInteger(rng, reach, grid.rows - 1 - reach);
    hole.centreColumn = uniformInteger(rng, reach, grid.cols - 1 - reach);
    const uint64_t shapeSeed = rng();
    const size_t centre = grid.index(hole.centreRow, hole.centreColumn);
    if (static_cast<double>(landDistance[centre]) * std::numbers::sqrt2 <= innerRadius ||
        blocked[centre]) {
      continue;  // cheap early rejection; the random stream is the same either way
    }
    const std::vector<Offset> shape = blobOffsets(diameterSamples, shapeSeed);
    bool fits = true;
    for (const Offset& o : shape) {
      const int64_t row = hole.centreRow + o.row, column = hole.centreColumn + o.column;
      // The sample and its 8-neighbour ring must be land and free.
      for (int64_t r = row - 1; r <= row + 1 && fits; ++r) {
        for (int64_t c = column - 1; c <= column + 1 && fits; ++c) {
          const size_t index = grid.index(r, c);
          fits = isLand(grid.samples[index]) && !blocked[index];
        }
      }
      if (!fits) break;
      hole.samples.push_back(grid.index(row, column));
    }
    if (!fits) continue;
    block(grid, hole, placement.gapSamples, blocked);
    holes.push_back(std::move(hole));
  }
  return holes;
}

std::vector<uint8_t> voidMask(const conditioning::DemGrid& grid, const std::vector<Hole>& holes) {
  std::vector<uint8_t> mask(grid.samples.size(), 0);
  for (const Hole& hole : holes) {
    for (size_t index : hole.samples) mask[index] = 1;
  }
  return mask;
}

}  // namespace globe::bench_fill
