#include "dem/sea_classification.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "terrain/height_block.hpp"

namespace globe::dem {
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

// Marks every passable sample 8-connected to the seeds as sea.
void flood(const DemGrid& grid, const std::vector<uint8_t>& passable, std::vector<size_t> seeds,
           std::vector<SampleClass>& classes) {
  for (size_t i : seeds) classes[i] = SampleClass::Sea;
  const auto cols = static_cast<size_t>(grid.cols);
  while (!seeds.empty()) {
    const size_t i = seeds.back();
    seeds.pop_back();
    forEachOfEight(grid, static_cast<int64_t>(i / cols), static_cast<int64_t>(i % cols),
                   [&](int64_t r, int64_t c) {
                     const size_t j = grid.index(r, c);
                     if (passable[j] != 0 && classes[j] != SampleClass::Sea) {
                       classes[j] = SampleClass::Sea;
                       seeds.push_back(j);
                     }
                   });
  }
}

}  // namespace

SeaClassification classifySea(const DemGrid& grid, const CoarserSources* coarser) {
  SeaClassification result;
  const size_t count = grid.samples.size();
  result.classes.assign(count, SampleClass::Land);
  std::vector<uint8_t> passable(count, 0);
  for (int64_t row = 0; row < grid.rows; ++row) {
    for (int64_t column = 0; column < grid.cols; ++column) {
      const size_t i = grid.index(row, column);
      const int16_t sample = grid.samples[i];
      if (sample == terrain::kNoDataHeight) ++result.noDataSamples;
      if (sample != terrain::kNoDataHeight && sample > 0) continue;
      passable[i] = coarser == nullptr || coarser->allowSea(grid.longitudeDegrees(column),
                                                            grid.latitudeDegrees(row))
                        ? 1
                        : 0;
    }
  }

  // Open sea: passable samples on the grid's border (north and south rows; west and east
  // columns unless the grid wraps round the globe).
  std::vector<size_t> seeds;
  auto seed = [&](int64_t row, int64_t column) {
    if (passable[grid.index(row, column)] != 0) seeds.push_back(grid.index(row, column));
  };
  for (int64_t column = 0; column < grid.cols; ++column) {
    seed(0, column);
    if (grid.rows > 1) seed(grid.rows - 1, column);
  }
  for (int64_t row = 1; row + 1 < grid.rows && !grid.wrapsLongitude; ++row) {
    seed(row, 0);
    if (grid.cols > 1) seed(row, grid.cols - 1);
  }
  flood(grid, passable, std::move(seeds), result.classes);

  // Enclosed seas: a remaining passable basin, large and measured deep enough.
  std::vector<uint8_t> visited(count, 0);
  const auto cols = static_cast<size_t>(grid.cols);
  for (size_t start = 0; start < count; ++start) {
    if (passable[start] == 0 || visited[start] != 0 || result.classes[start] == SampleClass::Sea)
      continue;
    std::vector<size_t> basin{start};
    visited[start] = 1;
    double areaKm2 = 0;
    bool deep = false;
    for (size_t k = 0; k < basin.size(); ++k) {
      const auto row = static_cast<int64_t>(basin[k] / cols);
      const int16_t sample = grid.samples[basin[k]];
      areaKm2 += cellAreaKm2(grid, row);
      deep = deep || (sample != terrain::kNoDataHeight && sample <= kSeaBasinMinimumDepthMeters);
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
    if (result.classes[i] == SampleClass::Sea) {
      ++result.seaSamples;
    } else if (grid.samples[i] == terrain::kNoDataHeight) {
      result.classes[i] = SampleClass::Void;
      ++result.voidSamples;
    }
  }
  return result;
}

}  // namespace globe::dem
