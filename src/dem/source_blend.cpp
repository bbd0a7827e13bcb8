#include "dem/source_blend.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "dem/vertex_sample.hpp"
#include "terrain/height_block.hpp"

namespace globe::dem {
namespace {

double wrapLongitude(double longitudeDegrees) {
  if (longitudeDegrees > 180.0) return longitudeDegrees - 360.0;
  if (longitudeDegrees < -180.0) return longitudeDegrees + 360.0;
  return longitudeDegrees;
}

}  // namespace

double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

uint64_t blendIntoCoarser(DemGrid& grid, const CoarserSources& coarser,
                          const CoverageTest& sameOrFinerCovers, double marginDegrees) {
  if (!(marginDegrees > 0) || grid.rows < 2 || grid.cols < 2) return 0;
  const double west = grid.longitudeDegrees(0) - grid.columnStepDegrees / 2;
  const double east = grid.longitudeDegrees(grid.cols - 1) + grid.columnStepDegrees / 2;
  const double north = grid.latitudeDegrees(0) + grid.rowStepDegrees / 2;
  const double south = grid.latitudeDegrees(grid.rows - 1) - grid.rowStepDegrees / 2;
  const double outsideLongitude = grid.columnStepDegrees / 2,
               outsideLatitude = grid.rowStepDegrees / 2;

  // An edge blends where the point just beyond it lies in a coarser source and in no finer one.
  auto blendsAt = [&](double longitude, double latitude) {
    if (latitude > 90.0 || latitude < -90.0) return false;
    longitude = wrapLongitude(longitude);
    return !sameOrFinerCovers(longitude, latitude) &&
           coarser.heightMeters(longitude, latitude).has_value();
  };
  std::vector<uint8_t> westBlends(static_cast<size_t>(grid.rows)),
      eastBlends(static_cast<size_t>(grid.rows));
  for (int64_t row = 0; row < grid.rows && !grid.wrapsLongitude; ++row) {
    const double latitude = grid.latitudeDegrees(row);
    westBlends[static_cast<size_t>(row)] = blendsAt(west - outsideLongitude, latitude) ? 1 : 0;
    eastBlends[static_cast<size_t>(row)] = blendsAt(east + outsideLongitude, latitude) ? 1 : 0;
  }
  std::vector<uint8_t> northBlends(static_cast<size_t>(grid.cols)),
      southBlends(static_cast<size_t>(grid.cols));
  for (int64_t column = 0; column < grid.cols; ++column) {
    const double longitude = grid.longitudeDegrees(column);
    northBlends[static_cast<size_t>(column)] = blendsAt(longitude, north + outsideLatitude) ? 1 : 0;
    southBlends[static_cast<size_t>(column)] = blendsAt(longitude, south - outsideLatitude) ? 1 : 0;
  }

  uint64_t changed = 0;
  for (int64_t row = 0; row < grid.rows; ++row) {
    const double latitude = grid.latitudeDegrees(row);
    for (int64_t column = 0; column < grid.cols; ++column) {
      const double longitude = grid.longitudeDegrees(column);
      double distance = marginDegrees;
      const auto r = static_cast<size_t>(row);
      const auto c = static_cast<size_t>(column);
      if (westBlends[r] != 0) distance = std::min(distance, longitude - west);
      if (eastBlends[r] != 0) distance = std::min(distance, east - longitude);
      if (northBlends[c] != 0) distance = std::min(distance, north - latitude);
      if (southBlends[c] != 0) distance = std::min(distance, latitude - south);
      if (distance >= marginDegrees) continue;
      int16_t& sample = grid.samples[grid.index(row, column)];
      if (terrain::isWater(sample)) continue;
      const auto coarse = coarser.heightMeters(longitude, latitude);
      if (!coarse) continue;
      const double weight = smoothstep(distance / marginDegrees);
      const double blended = *coarse + weight * (static_cast<double>(sample) - *coarse);
      const int16_t value = landSample(blended);
      if (value != sample) {
        sample = value;
        ++changed;
      }
    }
  }
  return changed;
}

}  // namespace globe::dem
