// The fill benchmark's holes: on land with a land ring, away from the edge and from each other,
// 4-connected, the same for the same seed, and none where the land has no room.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "tools/bench_fill/hole_generator.hpp"

namespace globe::bench_fill {
namespace {

constexpr int16_t kNoData = -9999;

// 3″ samples: land (sloping, 100..260 m) inside a disc of radius landRadius around the middle,
// sea at 0 m outside it, and a 5×5 no-data void in the land.
conditioning::DemGrid islandGrid(int64_t side, double landRadius) {
  conditioning::DemGrid grid;
  grid.cols = grid.rows = side;
  grid.firstColumnLongitudeDegrees = 8;
  grid.firstRowLatitudeDegrees = 51;
  grid.columnStepDegrees = grid.rowStepDegrees = 1.0 / 1200;
  grid.samples.assign(static_cast<size_t>(side * side), 0);
  const double middle = 0.5 * static_cast<double>(side - 1);
  for (int64_t row = 0; row < side; ++row) {
    for (int64_t column = 0; column < side; ++column) {
      if (std::hypot(static_cast<double>(row) - middle, static_cast<double>(column) - middle) <=
          landRadius) {
        grid.samples[grid.index(row, column)] = static_cast<int16_t>(100 + row + column / 2);
      }
    }
  }
  for (int64_t row = side / 2; row < side / 2 + 5; ++row) {
    for (int64_t column = side / 3; column < side / 3 + 5; ++column) {
      grid.samples[grid.index(row, column)] = kNoData;
    }
  }
  return grid;
}

bool fourConnected(const conditioning::DemGrid& grid, const Hole& hole) {
  const std::set<size_t> inside(hole.samples.begin(), hole.samples.end());
  std::set<size_t> reached{hole.samples.front()};
  std::vector<size_t> stack{hole.samples.front()};
  while (!stack.empty()) {
    const size_t index = stack.back();
    stack.pop_back();
    const auto row = static_cast<int64_t>(index) / grid.cols;
    const auto column = static_cast<int64_t>(index) % grid.cols;
    for (const size_t next : {grid.index(row - 1, column), grid.index(row + 1, column),
                              grid.index(row, column - 1), grid.index(row, column + 1)}) {
      if (inside.count(next) && reached.insert(next).second) stack.push_back(next);
    }
  }
  return reached.size() == inside.size();
}

TEST(PlaceHoles, OnLandWithALandRingAwayFromTheEdgeAndFromEachOther) {
  const conditioning::DemGrid grid = islandGrid(200, 80);
  HolePlacement placement;
  placement.seed = 7;
  for (const double diameter : {3.0, 8.0, 20.0, 50.0}) {
    SCOPED_TRACE(diameter);
    const size_t wanted = diameter < 50 ? 10 : 2;
    const std::vector<Hole> holes = placeHoles(grid, diameter, wanted, placement);
    ASSERT_EQ(holes.size(), wanted);
    std::vector<int> owner(grid.samples.size(), -1);
    for (size_t h = 0; h < holes.size(); ++h) {
      const Hole& hole = holes[h];
      ASSERT_FALSE(hole.samples.empty());
      EXPECT_TRUE(std::is_sorted(hole.samples.begin(), hole.samples.end()));
      EXPECT_TRUE(std::binary_search(hole.samples.begin(), hole.samples.end(),
                                     grid.index(hole.centreRow, hole.centreColumn)));
      EXPECT_TRUE(fourConnected(grid, hole));
      const double area = static_cast<double>(hole.samples.size());
      EXPECT_GT(area, 0.4 * std::numbers::pi * diameter * diameter / 4);
      EXPECT_LT(area, 1.8 * std::numbers::pi * diameter * diameter / 4 + 5);
      for (size_t index : hole.samples) {
        const auto row = static_cast<int64_t>(index) / grid.cols;
        const auto column = static_cast<int64_t>(index) % grid.cols;
        EXPECT_GE(std::min({row, column, grid.rows - 1 - row, grid.cols - 1 - column}),
                  placement.edgeMarginSamples);
        for (int64_t r = row - 1; r <= row + 1; ++r) {
          for (int64_t c = column - 1; c <= column + 1; ++c) {
            EXPECT_TRUE(isLand(grid.at(r, c))) << "row " << r << " column " << c;
          }
        }
        owner[index] = static_cast<int>(h);
      }
    }
    // No sample of one hole within gapSamples (Chebyshev) of another hole.
    const int64_t gap = placement.gapSamples;
    for (size_t h = 0; h < holes.size(); ++h) {
      for (size_t index : holes[h].samples) {
        const auto row = static_cast<int64_t>(index) / grid.cols;
        const auto column = static_cast<int64_t>(index) % grid.cols;
        for (int64_t r = std::max<int64_t>(0, row - gap); r <= std::min(grid.rows - 1, row + gap);
             ++r) {
          for (int64_t c = std::max<int64_t>(0, column - gap);
               c <= std::min(grid.cols - 1, column + gap); ++c) {
            const int other = owner[grid.index(r, c)];
            EXPECT_TRUE(other < 0 || other == static_cast<int>(h));
          }
        }
      }
    }
  }
}

TEST(PlaceHoles, SameSeedSameHolesOtherSeedOtherHoles) {
  const conditioning::DemGrid grid = islandGrid(200, 80);
  HolePlacement placement;
  placement.seed = 11;
  const std::vector<Hole> first = placeHoles(grid, 8, 20, placement);
  const std::vector<Hole> again = placeHoles(grid, 8, 20, placement);
  ASSERT_EQ(first.size(), again.size());
  for (size_t h = 0; h < first.size(); ++h) EXPECT_EQ(first[h].samples, again[h].samples);
  EXPECT_EQ(voidMask(grid, first), voidMask(grid, again));
  placement.seed = 12;
  EXPECT_NE(voidMask(grid, placeHoles(grid, 8, 20, placement)), voidMask(grid, first));
}

TEST(PlaceHoles, NoneWhereTheLandHasNoRoom) {
  // Land only as a 20-sample-wide strip: a 40-sample blob (at least 28 wide) never fits.
  conditioning::DemGrid grid = islandGrid(200, 0);
  for (int64_t row = 0; row < grid.rows; ++row) {
    for (int64_t column = 90; column < 110; ++column) grid.samples[grid.index(row, column)] = 50;
  }
  HolePlacement placement;
  placement.attemptsPerHole = 200;
  EXPECT_TRUE(placeHoles(grid, 40, 3, placement).empty());
  EXPECT_FALSE(placeHoles(grid, 8, 3, placement).empty());
}

TEST(VoidMask, FlagsExactlyTheHoleSamples) {
  const conditioning::DemGrid grid = islandGrid(200, 80);
  const std::vector<Hole> holes = placeHoles(grid, 20, 5, HolePlacement{});
  const std::vector<uint8_t> mask = voidMask(grid, holes);
  size_t holeSamples = 0;
  for (const Hole& hole : holes) holeSamples += hole.samples.size();
  EXPECT_EQ(static_cast<size_t>(std::count(mask.begin(), mask.end(), 1)), holeSamples);
  for (const Hole& hole : holes) {
    for (size_t index : hole.samples) EXPECT_EQ(mask[index], 1);
  }
}

}  // namespace
}  // namespace globe::bench_fill
