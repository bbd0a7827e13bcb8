#include "publish/tin_simplifier.hpp"

#include <algorithm>
#include <vector>

#include "publish/tin_decimation.hpp"
#include "publish/tin_grid.hpp"
#include "publish/tin_insertion.hpp"

namespace globe::publish {
namespace {

using tin::Grid;
using tin::heightPositions;
using tin::maxDistance;
using tin::Position;

GridTin simplify(const Grid& grid, double maxErrorMeters) {
  const double tolerance = std::max(0.0, maxErrorMeters);
  return tin::decimate(grid, tolerance, tin::greedyInsertion(grid, tolerance));
}

}  // namespace

GridTin simplifyTileGrid(const std::vector<double>& heightsMeters,
                         const std::vector<double>& apronHeightsMeters,
                         const std::vector<std::array<double, 3>>& ecefMeters, uint32_t side,
                         double maxErrorMeters) {
  const std::vector<Position> positions = heightPositions(heightsMeters, side);
  return simplify(Grid{positions, static_cast<int>(side), true, &ecefMeters, &apronHeightsMeters},
                  maxErrorMeters);
}

GridTin simplifyGrid(const std::vector<double>& heightsMeters, uint32_t side,
                     double maxErrorMeters) {
  const std::vector<Position> positions = heightPositions(heightsMeters, side);
  return simplify(Grid{positions, static_cast<int>(side), false}, maxErrorMeters);
}

double maxTinErrorMeters(const std::vector<double>& heightsMeters, uint32_t side,
                         const GridTin& tin) {
  const std::vector<Position> positions = heightPositions(heightsMeters, side);
  return maxDistance(Grid{positions, static_cast<int>(side), false}, tin);
}

double maxTileTinErrorMeters(const std::vector<double>& heightsMeters,
                             const std::vector<std::array<double, 3>>& ecefMeters, uint32_t side,
                             const GridTin& tin) {
  const std::vector<Position> positions = heightPositions(heightsMeters, side);
  return maxDistance(Grid{positions, static_cast<int>(side), true, &ecefMeters}, tin);
}

}  // namespace globe::publish
