#include "conditioning/grid_coarser_sources.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "conditioning/vertex_sample.hpp"
#include "terrain/height_block.hpp"

namespace globe::conditioning {
namespace {

// The 2×2 samples around a point and the point's fractions between them.
struct Support {
  std::array<int16_t, 4> samples{};  // north-west, north-east, south-west, south-east
  double tu = 0, tv = 0;
  int64_t row0 = 0, column0 = 0;  // of the north-west sample (column not wrapped)
};

int64_t wrapColumn(int64_t column, int64_t columns) {
  const int64_t wrapped = column % columns;
  return wrapped < 0 ? wrapped + columns : wrapped;
}

Support supportAt(const DemGrid& grid, double longitudeDegrees, double latitudeDegrees) {
  double u = (longitudeDegrees - grid.firstColumnLongitudeDegrees) / grid.columnStepDegrees;
  if (grid.wrapsLongitude) {
    const double turn = static_cast<double>(grid.cols);
    u -= turn * std::floor(u / turn);
  } else {
    u = std::clamp(u, 0.0, static_cast<double>(grid.cols - 1));
  }
  const double v =
      std::clamp((grid.firstRowLatitudeDegrees - latitudeDegrees) / grid.rowStepDegrees, 0.0,
                 static_cast<double>(grid.rows - 1));
  const auto c0 = static_cast<int64_t>(std::floor(u));
  const auto r0 = static_cast<int64_t>(std::floor(v));
  const int64_t c1 =
      grid.wrapsLongitude ? wrapColumn(c0 + 1, grid.cols) : std::min(c0 + 1, grid.cols - 1);
  const int64_t r1 = std::min(r0 + 1, grid.rows - 1);
  const int64_t c0w = grid.wrapsLongitude ? wrapColumn(c0, grid.cols) : c0;
  Support s;
  s.samples = {grid.at(r0, c0w), grid.at(r0, c1), grid.at(r1, c0w), grid.at(r1, c1)};
  s.tu = u - static_cast<double>(c0);
  s.tv = v - static_cast<double>(r0);
  s.row0 = r0;
  s.column0 = c0;
  return s;
}

}  // namespace

bool gridCovers(const DemGrid& grid, double longitudeDegrees, double latitudeDegrees) {
  if (grid.cols < 1 || grid.rows < 1) return false;
  const double north = grid.firstRowLatitudeDegrees + grid.rowStepDegrees / 2;
  const double south = grid.latitudeDegrees(grid.rows - 1) - grid.rowStepDegrees / 2;
  if (latitudeDegrees > north || latitudeDegrees < south) return false;
  if (grid.wrapsLongitude) return true;
  const double west = grid.firstColumnLongitudeDegrees - grid.columnStepDegrees / 2;
  const double east = grid.longitudeDegrees(grid.cols - 1) + grid.columnStepDegrees / 2;
  return longitudeDegrees >= west && longitudeDegrees <= east;
}

double bilinearSurfaceMeters(const DemGrid& grid, double longitudeDegrees, double latitudeDegrees) {
  const Support s = supportAt(grid, longitudeDegrees, latitudeDegrees);
  return terrain::surfaceHeightMeters(interpolateSample(s.samples, s.tu, s.tv));
}

bool GridCoarserSources::allowSea(double longitudeDegrees, double latitudeDegrees) const {
  for (const DemGrid* grid : grids_) {
    if (!gridCovers(*grid, longitudeDegrees, latitudeDegrees)) continue;
    // The 4×4 samples around the point: a coarse grid places a coast within about a cell, so it
    // says land only where it is land a whole cell around (an estuary narrower than a 20′ cell
    // stays sea; a summit void stays land).
    const Support s = supportAt(*grid, longitudeDegrees, latitudeDegrees);
    bool land = true;
    for (int64_t dr = -1; dr <= 2 && land; ++dr) {
      const int64_t r = std::clamp<int64_t>(s.row0 + dr, 0, grid->rows - 1);
      for (int64_t dc = -1; dc <= 2 && land; ++dc) {
        int64_t c = s.column0 + dc;
        c = grid->wrapsLongitude ? wrapColumn(c, grid->cols)
                                 : std::clamp<int64_t>(c, 0, grid->cols - 1);
        const int16_t sample = grid->at(r, c);
        land = !terrain::isWater(sample) && sample > 0;
      }
    }
    if (land) return false;
  }
  return true;
}

std::optional<double> GridCoarserSources::heightMeters(double longitudeDegrees,
                                                       double latitudeDegrees) const {
  for (const DemGrid* grid : grids_) {
    if (gridCovers(*grid, longitudeDegrees, latitudeDegrees)) {
      return bilinearSurfaceMeters(*grid, longitudeDegrees, latitudeDegrees);
    }
  }
  return std::nullopt;
}

std::optional<int16_t> GridCoarserSources::sample(double longitudeDegrees,
                                                  double latitudeDegrees) const {
  for (const DemGrid* grid : grids_) {
    if (gridCovers(*grid, longitudeDegrees, latitudeDegrees)) {
      const Support s = supportAt(*grid, longitudeDegrees, latitudeDegrees);
      const int16_t sample = interpolateSample(s.samples, s.tu, s.tv);
      if (!terrain::isWater(sample)) return sample;
      // Water only where the surface (floors where measured, 0 m where not) is at or below 0 m:
      // where the nearest sample made a coast vertex water above it, the land's height there.
      auto floorOrLand = [&](size_t k) {
        return terrain::surfaceHeightMeters(s.samples[k], terrain::SeaSurface::SeaFloor);
      };
      const double heightMeters =
          (1 - s.tv) * ((1 - s.tu) * floorOrLand(0) + s.tu * floorOrLand(1)) +
          s.tv * ((1 - s.tu) * floorOrLand(2) + s.tu * floorOrLand(3));
      return heightMeters > 0.0 ? landSample(heightMeters) : sample;
    }
  }
  return std::nullopt;
}

}  // namespace globe::conditioning
