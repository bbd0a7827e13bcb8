// SRTM30-like block means: the trapezoid rule puts a plane's mean at the cell centre exactly.
#include <gtest/gtest.h>

#include "tools/bench_fill/block_average.hpp"

namespace globe::bench_fill {
namespace {

conditioning::DemGrid planeGrid() {
  conditioning::DemGrid fine;
  fine.cols = fine.rows = 21;
  fine.firstColumnLongitudeDegrees = 8;
  fine.firstRowLatitudeDegrees = 51;
  fine.columnStepDegrees = fine.rowStepDegrees = 1.0 / 1200;
  for (int64_t row = 0; row < fine.rows; ++row) {
    for (int64_t column = 0; column < fine.cols; ++column) {
      fine.samples.push_back(static_cast<int16_t>(100 + 2 * row + 3 * column));
    }
  }
  return fine;
}

TEST(BlockAverage, PlaneAveragesToItsValueAtTheCellCentre) {
  const conditioning::DemGrid coarse = blockAverage(planeGrid(), 10);
  ASSERT_EQ(coarse.rows, 2);
  ASSERT_EQ(coarse.cols, 2);
  EXPECT_DOUBLE_EQ(coarse.columnStepDegrees, 1.0 / 120);
  EXPECT_DOUBLE_EQ(coarse.firstColumnLongitudeDegrees, 8 + 1.0 / 240);
  EXPECT_DOUBLE_EQ(coarse.firstRowLatitudeDegrees, 51 - 1.0 / 240);
  for (int64_t row = 0; row < 2; ++row) {
    for (int64_t column = 0; column < 2; ++column) {
      EXPECT_EQ(coarse.at(row, column), 100 + 2 * (10 * row + 5) + 3 * (10 * column + 5));
    }
  }
}

TEST(BlockAverage, LeavesNoDataOut) {
  conditioning::DemGrid fine = planeGrid();
  for (int16_t& h : fine.samples) h = 50;
  fine.samples[fine.index(3, 4)] = -9999;
  for (int64_t row = 10; row < 21; ++row) {
    for (int64_t column = 10; column < 21; ++column) fine.samples[fine.index(row, column)] = -9999;
  }
  const conditioning::DemGrid coarse = blockAverage(fine, 10);
  EXPECT_EQ(coarse.at(0, 0), 50);
  EXPECT_EQ(coarse.at(1, 1), -9999);
}

}  // namespace
}  // namespace globe::bench_fill
