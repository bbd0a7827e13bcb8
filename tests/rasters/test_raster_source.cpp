// SampleGrid snapping and publishing, and the native GTOPO30 RasterSource: bounds, wrapping,
// threads.
#include "rasters/raster_source.hpp"

#include <gtest/gtest.h>

#include <thread>

#include "rasters/gtopo30.hpp"
#include "tests/support/test_io_util.hpp"

namespace globe::rasters {
namespace {

using globe::testing::TempDir;

geo::SampleGrid gridOf(const Gtopo30Header& h) {
  geo::SampleGrid g;
  g.cols = h.cols;
  g.rows = h.rows;
  g.firstColumnLongitudeDegrees = h.ulxMapDegrees;
  g.firstRowLatitudeDegrees = h.ulyMapDegrees;
  g.columnStepDegrees = h.xDimDegrees;
  g.rowStepDegrees = h.yDimDegrees;
  return g;
}

TEST(SnapSampleGrid, RealHeaders) {
  GLOBE_REQUIRE_DEM_DIR(dir, "gtopo30");
  auto etopo = readGtopo30(dir / "ETOPO20.HDR");
  ASSERT_TRUE(etopo.ok()) << etopo.error();
  // ETOPO20.HDR: XDIM 0.3333333, ULXMAP -179.83333335, ULYMAP 89.8333154.
  const geo::SampleGrid e = snapSampleGrid(gridOf(etopo->header));
  EXPECT_EQ(e.columnStepDegrees, 1.0 / 3);
  EXPECT_EQ(e.rowStepDegrees, 1.0 / 3);
  EXPECT_EQ(e.firstColumnLongitudeDegrees, -1079.0 / 6);
  EXPECT_EQ(e.firstRowLatitudeDegrees, 539.0 / 6);
  EXPECT_TRUE(e.wrapsLongitude);
  EXPECT_EQ(e.westDegrees(), -180.0);
  EXPECT_EQ(e.eastDegrees(), 180.0);
  EXPECT_NEAR(e.northDegrees(), 90.0, 1e-12);
  EXPECT_NEAR(e.southDegrees(), -90.0, 1e-12);

  auto w = readGtopo30(dir / "W002N52.HDR");
  ASSERT_TRUE(w.ok()) << w.error();
  const geo::SampleGrid g = snapSampleGrid(gridOf(w->header));
  EXPECT_EQ(g.columnStepDegrees, 1.0 / 120);
  EXPECT_EQ(g.firstColumnLongitudeDegrees, -479.0 / 240);
  EXPECT_EQ(g.firstRowLatitudeDegrees, 12959.0 / 240);
  EXPECT_FALSE(g.wrapsLongitude);
  EXPECT_NEAR(g.westDegrees(), -2.0, 1e-12);
  EXPECT_NEAR(g.eastDegrees(), 0.0, 1e-12);
  EXPECT_NEAR(g.northDegrees(), 54.0, 1e-12);
  EXPECT_NEAR(g.southDegrees(), 52.0, 1e-12);

  // 3″ SRTM: samples on whole degrees, cells reaching half a cell beyond the degree square.
  auto fuji = readGtopo30(dir / "E138N35_FUJI.HDR");
  ASSERT_TRUE(fuji.ok()) << fuji.error();
  const geo::SampleGrid f = snapSampleGrid(gridOf(fuji->header));
  EXPECT_EQ(f.columnStepDegrees, 1.0 / 1200);
  EXPECT_EQ(f.rowStepDegrees, 1.0 / 1200);
  EXPECT_EQ(f.firstColumnLongitudeDegrees, 138.0);
  EXPECT_EQ(f.firstRowLatitudeDegrees, 36.0);
  EXPECT_NEAR(f.westDegrees(), 138.0 - 1.0 / 2400, 1e-12);
  EXPECT_NEAR(f.eastDegrees(), 139.0 + 1.0 / 2400, 1e-12);
}

TEST(SnapSampleGrid, GdalStyleAndUnsnappableValues) {
  geo::SampleGrid g;
  g.cols = g.rows = 1201;
  g.columnStepDegrees = g.rowStepDegrees = 0.000833333333333;  // as GDAL reports 3″
  g.firstColumnLongitudeDegrees = 7.999583333333334 + 0.000833333333333 / 2;
  g.firstRowLatitudeDegrees = 51.000416666666666 - 0.000833333333333 / 2;
  const geo::SampleGrid s = snapSampleGrid(g);
  EXPECT_EQ(s.columnStepDegrees, 1.0 / 1200);
  EXPECT_EQ(s.firstColumnLongitudeDegrees, 8.0);
  EXPECT_EQ(s.firstRowLatitudeDegrees, 51.0);

  // 1/0.0123 = 81.3: not near an integer, left exactly as it was.
  geo::SampleGrid odd = g;
  odd.columnStepDegrees = 0.0123;
  odd.firstColumnLongitudeDegrees = 0.00615;
  EXPECT_EQ(snapSampleGrid(odd).columnStepDegrees, 0.0123);
  EXPECT_EQ(snapSampleGrid(odd).firstColumnLongitudeDegrees, 0.00615);

  // 1/10800.4 is within 1e-4 of 10800, but over 10800 columns 1/10800 would move the last
  // sample by 0.4 of a cell: left alone.
  geo::SampleGrid fine = g;
  fine.cols = 10800;
  fine.columnStepDegrees = 1 / 10800.4;
  EXPECT_EQ(snapSampleGrid(fine).columnStepDegrees, 1 / 10800.4);
  fine.cols = 1000;  // 0.037 of a cell: snapped
  EXPECT_EQ(snapSampleGrid(fine).columnStepDegrees, 1.0 / 10800);

  // Step snaps but the centre is far from any half step: centre untouched.
  odd.columnStepDegrees = 0.5;
  odd.firstColumnLongitudeDegrees = 0.1;
  EXPECT_EQ(snapSampleGrid(odd).firstColumnLongitudeDegrees, 0.1);
  EXPECT_EQ(snapSampleGrid(odd).columnStepDegrees, 0.5);

  // Degenerate input is returned, not crashed on.
  geo::SampleGrid zero;
  EXPECT_EQ(snapSampleGrid(zero).columnStepDegrees, 0.0);
  EXPECT_FALSE(snapSampleGrid(zero).wrapsLongitude);
}

TEST(PublishGrid, WrappingGridStartingAt20EIsCutToOneTurnAndRecentred) {
  geo::SampleGrid g;  // etopo20.cdf as GDAL describes it
  g.cols = 1081;
  g.rows = 540;
  g.columnStepDegrees = g.rowStepDegrees = 0.3333333;
  g.firstColumnLongitudeDegrees = 20.00000005 + 0.3333333 / 2;
  g.firstRowLatitudeDegrees = 89.99998205 - 0.3333333 / 2;
  const detail::PublishedGrid p = detail::publishGrid(g);
  EXPECT_TRUE(p.grid.wrapsLongitude);
  EXPECT_EQ(p.grid.cols, 1080);
  EXPECT_EQ(p.grid.firstColumnLongitudeDegrees, -1079.0 / 6);
  EXPECT_EQ(p.grid.firstRowLatitudeDegrees, 539.0 / 6);
  EXPECT_EQ(p.columns.period, 1080);
  EXPECT_EQ(p.columns.offset, 480);  // column 480 of the source is centred on 180 + 1/6 = -179 5/6

  // A 0..360 grid, one already starting at -180, and regional grids beyond ±180.
  g.cols = 360;
  g.columnStepDegrees = 1;
  g.firstColumnLongitudeDegrees = 0.5;
  EXPECT_EQ(detail::publishGrid(g).columns.offset, 180);
  EXPECT_EQ(detail::publishGrid(g).grid.firstColumnLongitudeDegrees, -179.5);
  g.firstColumnLongitudeDegrees = -179.5;
  EXPECT_EQ(detail::publishGrid(g).columns.offset, 0);
  g.cols = 10;
  g.firstColumnLongitudeDegrees = 200.5;
  const detail::PublishedGrid regional = detail::publishGrid(g);
  EXPECT_FALSE(regional.grid.wrapsLongitude);
  EXPECT_EQ(regional.grid.firstColumnLongitudeDegrees, -159.5);
  EXPECT_EQ(regional.columns.offset, 0);
  g.firstColumnLongitudeDegrees = -184.5;  // straddles -180: left as it is
  EXPECT_EQ(detail::publishGrid(g).grid.firstColumnLongitudeDegrees, -184.5);
  g.firstColumnLongitudeDegrees = -549.5;  // wholly west of -180: moved by whole turns
  EXPECT_EQ(detail::publishGrid(g).grid.firstColumnLongitudeDegrees, -189.5 + 360);
}

TEST(Gtopo30Source, ReadsRowsEqualToTheWholeRaster) {
  GLOBE_REQUIRE_DEM_DIR(dir, "gtopo30");
  for (const std::string& stem : globe::testing::gtopo30Stems()) {
    auto raster = readGtopo30(dir / (stem + ".DEM"));
    ASSERT_TRUE(raster.ok()) << raster.error();
    auto source = openRasterSource(dir / (stem + ".DEM"));
    ASSERT_TRUE(source.ok()) << source.error();
    const RasterSource& s = **source;
    EXPECT_EQ(s.formatName(), "GTOPO30");
    EXPECT_EQ(s.path(), (dir / (stem + ".DEM")).string());
    ASSERT_EQ(s.grid().cols, raster->header.cols);
    ASSERT_EQ(s.grid().rows, raster->header.rows);
    std::vector<int16_t> row(static_cast<size_t>(s.grid().cols));
    for (int64_t r = 0; r < s.grid().rows; ++r) {
      ASSERT_TRUE(s.readRow(r, 0, s.grid().cols, row.data()).ok());
      ASSERT_TRUE(
          std::equal(row.begin(), row.end(), raster->heights.begin() + r * raster->header.cols))
          << stem << " row " << r;
    }
  }
}

TEST(Gtopo30Source, OutOfRangeReadsAreErrors) {
  GLOBE_REQUIRE_DEM_DIR(dir, "gtopo30");
  auto source = openGtopo30Source(dir / "W002N52.DEM");
  ASSERT_TRUE(source.ok()) << source.error();
  const RasterSource& s = **source;
  std::vector<int16_t> out(300, 42);
  struct Case {
    int64_t row, first, count;
  };
  for (const Case& c : {Case{-1, 0, 1}, Case{240, 0, 1}, Case{0, -1, 1}, Case{0, 0, 241},
                        Case{0, 239, 2}, Case{0, 241, 0}, Case{0, 0, -1}, Case{INT64_MAX, 0, 1},
                        Case{0, INT64_MAX, 1}, Case{0, 1, INT64_MAX}}) {
    auto r = s.readRow(c.row, c.first, c.count, out.data());
    ASSERT_FALSE(r.ok()) << c.row << " " << c.first << " " << c.count;
    EXPECT_NE(r.error().find("W002N52.DEM: cannot read"), std::string::npos) << r.error();
  }
  EXPECT_EQ(out[0], 42);
  EXPECT_TRUE(s.readRow(239, 240, 0, out.data()).ok());  // empty read at the end is fine
  EXPECT_TRUE(s.readRow(239, 200, 40, out.data()).ok());
}

TEST(Gtopo30Source, WrapsAcrossTheAntimeridian) {
  GLOBE_REQUIRE_DEM_DIR(dir, "gtopo30");
  auto raster = readGtopo30(dir / "ETOPO20");
  ASSERT_TRUE(raster.ok()) << raster.error();
  auto source = openGtopo30Source(dir / "ETOPO20");
  ASSERT_TRUE(source.ok()) << source.error();
  const RasterSource& s = **source;
  ASSERT_TRUE(s.grid().wrapsLongitude);
  ASSERT_EQ(s.grid().cols, 1080);
  const int64_t row = 300;
  // 1070 .. 1079 then 0 .. 9, and the same starting from -10; and more than a full turn.
  for (int64_t first : {int64_t{1070}, int64_t{-10}, int64_t{1070 + 3 * 1080}}) {
    std::vector<int16_t> out(20 + 1080);
    ASSERT_TRUE(s.readRow(row, first, static_cast<int64_t>(out.size()), out.data()).ok());
    for (size_t i = 0; i < out.size(); ++i) {
      ASSERT_EQ(out[i], raster->at(row, static_cast<int64_t>((1070 + i) % 1080))) << i;
    }
  }
}

TEST(Gtopo30Source, ConcurrentReadsAgree) {
  GLOBE_REQUIRE_DEM_DIR(dir, "gtopo30");
  auto raster = readGtopo30(dir / "N50E009.DEM");
  ASSERT_TRUE(raster.ok()) << raster.error();
  auto source = openRasterSource(dir / "N50E009.HDR");
  ASSERT_TRUE(source.ok()) << source.error();
  std::vector<int> bad(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      std::vector<int16_t> row(1201);
      for (int64_t r = t; r < 1201; r += 4) {
        if (!(*source)->readRow(r, 0, 1201, row.data()).ok() ||
            !std::equal(row.begin(), row.end(), raster->heights.begin() + r * 1201)) {
          ++bad[static_cast<size_t>(t)];
        }
      }
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(bad, std::vector<int>(4, 0));
}

TEST(Gtopo30Source, ForeignNoDataBecomesMinus9999) {
  TempDir tmp;
  Gtopo30Raster r;
  r.header.rows = 1;
  r.header.cols = 3;
  r.header.noData = -32768;
  r.header.ulxMapDegrees = r.header.ulyMapDegrees = 0;
  r.header.xDimDegrees = r.header.yDimDegrees = 1;
  r.heights = {-32768, -9999, 5};
  ASSERT_TRUE(writeGtopo30(tmp / "S", r).ok());
  auto source = openRasterSource(tmp / "S.DEM");
  ASSERT_TRUE(source.ok()) << source.error();
  int16_t out[3];
  ASSERT_TRUE((*source)->readRow(0, 0, 3, out).ok());
  EXPECT_EQ(out[0], -9999);
  EXPECT_EQ(out[1], -9999);
  EXPECT_EQ(out[2], 5);
}

}  // namespace
}  // namespace globe::rasters
