#include "conditioning/sea_classification.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "terrain/height_block.hpp"

namespace globe::conditioning {
namespace {

constexpr double kEarthRadiusKm = 6371.0;

// Calls f(row, column) for the 8 neighbours (columns wrap on wrapping grids).
template <typename F>
void forEachOfEight(const DemGrid& grid, int64_t row, int64_t column, F&& f) {
  for (int64_t dr = -1; dr <= 1; ++dr) {
    const int64_t r = row + dr;
    if (r < 0 || r >= grid.rows) continue;
    for (int64_t dc = -1; dc <= 1; ++dc) {
      if (dr == 0 && dc == 0) continue;
      int64_t c = column + dc;
      if (c < 0 || c >= grid.cols) {
        if (!grid.wrapsLongitude) continue;
        c = (c + grid.cols) % grid.cols;
      }
      f(r, c);
    }
  }
}

double cellAreaKm2(const DemGrid& grid, int64_t row) {
  const double toRadians = std::numbers::pi / 180.0;
  const double latitude = std::clamp(grid.latitudeDegrees(row), -90.0, 90.0) * toRadians;
  return kEarthRadiusKm * kEarthRadiusKm * grid.rowStepDegrees * toRadians *
         grid.columnStepDegrees * toRadians * std::cos(latitude);
}

// Every sample with inSet set that is 8-connected through the set to a seed; the seeds first.
std::vector<uint8_t> reach(const DemGrid& grid, const std::vector<uint8_t>& inSet,
                           std::vector<size_t> seeds) {
  std::vector<uint8_t> reached(inSet.size(), 0);
  for (size_t i : seeds) reached[i] = 1;
  const auto cols = static_cast<size_t>(grid.cols);
  while (!seeds.empty()) {
    const size_t i = seeds.back();
    seeds.pop_back();
    forEachOfEight(grid, static_cast<int64_t>(i / cols), static_cast<int64_t>(i % cols),
                   [&](int64_t r, int64_t c) {
                     const size_t j = grid.index(r, c);
                     if (inSet[j] != 0 && reached[j] == 0) {
                       reached[j] = 1;
                       seeds.push_back(j);
                     }
                   });
  }
  return reached;
}

// The samples of the set on the grid's border (north and south rows; west and east columns
// unless the grid wraps round the globe).
std::vector<size_t> onBorder(const DemGrid& grid, const std::vector<uint8_t>& inSet) {
  std::vector<size_t> seeds;
  auto seed = [&](int64_t row, int64_t column) {
    if (inSet[grid.index(row, column)] != 0) seeds.push_back(grid.index(row, column));
  };
  for (int64_t column = 0; column < grid.cols; ++column) {
    seed(0, column);
    if (grid.rows > 1) seed(grid.rows - 1, column);
  }
  for (int64_t row = 1; row + 1 < grid.rows && !grid.wrapsLongitude; ++row) {
    seed(row, 0);
    if (grid.cols > 1) seed(row, grid.cols - 1);
  }
  return seeds;
}

// The no-data samples outside the footprint: each 8-connected no-data region reaching the border
// that meets it along a long stretch or covers much of the grid (kOutsideBorderFraction,
// kOutsideAreaFraction); a region the edge only cuts through is a hole like any other.
std::vector<uint8_t> outsideFootprint(const DemGrid& grid, const std::vector<uint8_t>& noData) {
  const size_t count = grid.samples.size();
  const auto cols = static_cast<size_t>(grid.cols);
  const double longStretch =
      kOutsideBorderFraction * static_cast<double>(std::min(grid.rows, grid.cols));
  const double largeArea = kOutsideAreaFraction * static_cast<double>(count);
  auto onEdge = [&](size_t i) {
    const auto row = static_cast<int64_t>(i / cols), column = static_cast<int64_t>(i % cols);
    return row == 0 || row == grid.rows - 1 ||
           (!grid.wrapsLongitude && (column == 0 || column == grid.cols - 1));
  };
  std::vector<uint8_t> outside(count, 0), seen(count, 0);
  for (size_t seed : onBorder(grid, noData)) {
    if (seen[seed] != 0) continue;
    std::vector<size_t> region{seed};
    seen[seed] = 1;
    size_t contact = 0;
    for (size_t k = 0; k < region.size(); ++k) {
      contact += onEdge(region[k]) ? 1 : 0;
      forEachOfEight(grid, static_cast<int64_t>(region[k] / cols),
                     static_cast<int64_t>(region[k] % cols), [&](int64_t r, int64_t c) {
                       const size_t j = grid.index(r, c);
                       if (noData[j] != 0 && seen[j] == 0) seen[j] = 1, region.push_back(j);
                     });
    }
    if (static_cast<double>(contact) < longStretch &&
        static_cast<double>(region.size()) < largeArea) {
      continue;
    }
    for (size_t i : region) outside[i] = 1;
  }
  return outside;
}

}  // namespace

SeaClassification classifySea(const DemGrid& grid, const CoarserSources* coarser,
                              bool noDataIsWater) {
  SeaClassification result;
  const size_t count = grid.samples.size();
  result.classes.assign(count, SampleClass::Land);

  // Outside the footprint: no data reaching the border through no data along a long stretch,
  // where a coarser source covers it (without one there is nothing to show through: a void).
  std::vector<uint8_t> noData(count, 0);
  for (size_t i = 0; i < count; ++i) {
    if (grid.samples[i] == terrain::kNoDataHeight) {
      noData[i] = 1;
      ++result.noDataSamples;
    }
  }
  const std::vector<uint8_t> reachesBorder =
      coarser == nullptr ? std::vector<uint8_t>(count, 0) : outsideFootprint(grid, noData);

  // Water the coarser sources say is there (no data under coarser water, and the footprint's
  // outside where it is water) and measured samples at or below 0 m that may be sea.
  std::vector<uint8_t> passable(count, 0);
  std::vector<size_t> openWater;
  for (int64_t row = 0; row < grid.rows; ++row) {
    for (int64_t column = 0; column < grid.cols; ++column) {
      const size_t i = grid.index(row, column);
      const int16_t sample = grid.samples[i];
      const double longitude = grid.longitudeDegrees(column), latitude = grid.latitudeDegrees(row);
      if (noData[i] != 0) {
        const std::optional<int16_t> coarse =
            coarser != nullptr ? coarser->sample(longitude, latitude) : std::nullopt;
        if (reachesBorder[i] != 0 && coarse && !noDataIsWater) {
          result.classes[i] = SampleClass::Outside;
        }
        if (noDataIsWater || (coarse && terrain::isWater(*coarse))) {
          passable[i] = 1;
          openWater.push_back(i);
          if (result.classes[i] != SampleClass::Outside) result.classes[i] = SampleClass::Sea;
        }
        continue;
      }
      if (sample > 0) continue;
      passable[i] = coarser == nullptr || coarser->allowSea(longitude, latitude) ? 1 : 0;
    }
  }
  // Measured samples connected to open water: the border's, or the coarser sources' water.
  std::vector<size_t> seeds = onBorder(grid, passable);
  for (size_t i : seeds) {
    if (noData[i] == 0) openWater.push_back(i);
  }
  const std::vector<uint8_t> sea = reach(grid, passable, std::move(openWater));
  for (size_t i = 0; i < count; ++i) {
    if (sea[i] != 0 && noData[i] == 0) result.classes[i] = SampleClass::Sea;
  }

  // Enclosed seas: a remaining basin of measured samples, large and deep enough.
  std::vector<uint8_t> visited(count, 0);
  const auto cols = static_cast<size_t>(grid.cols);
  for (size_t start = 0; start < count; ++start) {
    if (passable[start] == 0 || visited[start] != 0 || sea[start] != 0) continue;
    std::vector<size_t> basin{start};
    visited[start] = 1;
    double areaKm2 = 0;
    bool deep = false;
    for (size_t k = 0; k < basin.size(); ++k) {
      const auto row = static_cast<int64_t>(basin[k] / cols);
      areaKm2 += cellAreaKm2(grid, row);
      deep = deep || grid.samples[basin[k]] <= kSeaBasinMinimumDepthMeters;
      forEachOfEight(grid, row, static_cast<int64_t>(basin[k] % cols), [&](int64_t r, int64_t c) {
        const size_t j = grid.index(r, c);
        if (passable[j] != 0 && visited[j] == 0) {
          visited[j] = 1;
          basin.push_back(j);
        }
      });
    }
    if (deep && areaKm2 >= kSeaBasinMinimumAreaKm2) {
      for (size_t i : basin) result.classes[i] = SampleClass::Sea;
    }
  }

  for (size_t i = 0; i < count; ++i) {
    switch (result.classes[i]) {
      case SampleClass::Sea:
        ++result.seaSamples;
        break;
      case SampleClass::Outside:
        ++result.outsideSamples;
        break;
      case SampleClass::Land:
        if (noData[i] != 0) {
          result.classes[i] = SampleClass::Void;
          ++result.voidSamples;
        }
        break;
      case SampleClass::Void:
        break;
    }
  }
  return result;
}

}  // namespace globe::conditioning
