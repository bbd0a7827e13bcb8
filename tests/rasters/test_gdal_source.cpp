// The GDAL RasterSource against the native reader and against the originals the GTOPO30 files
// were made from (SRTM .hgt, GeoTIFF, netCDF), plus synthetic projected/float/bottom-up rasters.
#include <cpl_conv.h>
#include <gdal.h>
#include <gtest/gtest.h>
#include <ogr_srs_api.h>

#include <cmath>
#include <limits>
#include <random>
#include <thread>

#include "rasters/gtopo30.hpp"
#include "rasters/raster_source.hpp"
#include "tests/support/epsg_wkt.hpp"
#include "tests/support/test_io_util.hpp"

namespace globe::rasters {
namespace {

using globe::testing::TempDir;

void expectSameGrid(const geo::SampleGrid& a, const geo::SampleGrid& b) {
  EXPECT_EQ(a.cols, b.cols);
  EXPECT_EQ(a.rows, b.rows);
  EXPECT_EQ(a.firstColumnLongitudeDegrees, b.firstColumnLongitudeDegrees);
  EXPECT_EQ(a.firstRowLatitudeDegrees, b.firstRowLatitudeDegrees);
  EXPECT_EQ(a.columnStepDegrees, b.columnStepDegrees);
  EXPECT_EQ(a.rowStepDegrees, b.rowStepDegrees);
  EXPECT_EQ(a.wrapsLongitude, b.wrapsLongitude);
}

std::vector<int16_t> readAll(const RasterSource& s) {
  const geo::SampleGrid& g = s.grid();
  std::vector<int16_t> all(static_cast<size_t>(g.cols * g.rows));
  for (int64_t r = 0; r < g.rows; ++r) {
    auto ok = s.readRow(r, 0, g.cols, all.data() + r * g.cols);
    EXPECT_TRUE(ok.ok()) << ok.error();
    if (!ok.ok()) break;
  }
  return all;
}

size_t countDifferences(const std::vector<int16_t>& a, const std::vector<int16_t>& b) {
  size_t n = 0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) n += a[i] != b[i];
  return n + std::max(a.size(), b.size()) - std::min(a.size(), b.size());
}

std::unique_ptr<RasterSource> open(const std::filesystem::path& path, bool forceGdal = false) {
  auto s = forceGdal ? openGdalSource(path) : openRasterSource(path);
  EXPECT_TRUE(s.ok()) << s.error();
  return s.ok() ? std::move(*s) : nullptr;
}

TEST(GdalSource, SameGridAndSamplesAsNativeOnEveryGtopo30File) {
  GLOBE_REQUIRE_DEM_DIR(dir, "gtopo30");
  size_t compared = 0;
  for (const std::string& stem : globe::testing::gtopo30Stems()) {
    SCOPED_TRACE(stem);
    auto native = open(dir / (stem + ".DEM"));
    auto gdal = open(dir / (stem + ".DEM"), true);
    ASSERT_TRUE(native && gdal);
    EXPECT_EQ(gdal->formatName(), "EHdr");
    expectSameGrid(native->grid(), gdal->grid());
    const auto a = readAll(*native), b = readAll(*gdal);
    EXPECT_EQ(countDifferences(a, b), 0u);
    compared += a.size();
  }
  EXPECT_EQ(compared, 57600u + 583200u + 4u * 1442401u);
}

TEST(GdalSource, SrtmHgtEqualsN50E008Dem) {
  GLOBE_REQUIRE_DEM_DIR(dir, "gtopo30");
  GLOBE_REQUIRE_DEM_DIR(original, "original");
  auto hgt = open(original / "N50E008.hgt");
  auto dem = open(dir / "N50E008.DEM");
  ASSERT_TRUE(hgt && dem);
  EXPECT_EQ(hgt->formatName(), "SRTMHGT");
  expectSameGrid(hgt->grid(), dem->grid());
  const auto a = readAll(*hgt), b = readAll(*dem);
  ASSERT_EQ(a.size(), 1201u * 1201u);
  // The .hgt has 50 voids (-32768, read as -9999); the .DEM holds -9999 in exactly those places
  // (its .STX range 62..885 leaves no-data out).
  EXPECT_EQ(std::count(a.begin(), a.end(), kNoDataHeight), 50);
  EXPECT_EQ(std::count(b.begin(), b.end(), kNoDataHeight), 50);
  EXPECT_EQ(countDifferences(a, b), 0u);
}

TEST(GdalSource, FujiGeoTiffEqualsFujiDem) {
  GLOBE_REQUIRE_DEM_DIR(dir, "gtopo30");
  GLOBE_REQUIRE_DEM_DIR(original, "original");
  auto tif = open(original / "mt_fuji_90m.tif");
  auto dem = open(dir / "E138N35_FUJI.DEM");
  ASSERT_TRUE(tif && dem);
  EXPECT_EQ(tif->formatName(), "GTiff");
  expectSameGrid(tif->grid(), dem->grid());
  const auto a = readAll(*tif), b = readAll(*dem);
  // The tif's -32768 voids read as -9999: 2437 of them, where the .DEM has its 2437 no-data.
  EXPECT_EQ(std::count(a.begin(), a.end(), kNoDataHeight), 2437);
  EXPECT_EQ(countDifferences(a, b), 0u);
}

TEST(GdalSource, NetcdfEtopo20WrapsAndMatchesEtopo20Dem) {
  GLOBE_REQUIRE_DEM_DIR(dir, "gtopo30");
  GLOBE_REQUIRE_DEM_DIR(original, "original");
  auto cdf = open(original / "etopo20.cdf");
  auto dem = open(dir / "ETOPO20.DEM");
  ASSERT_TRUE(cdf && dem);
  EXPECT_EQ(cdf->formatName(), "netCDF");
  // 1081 float columns from 20°E (the last repeats the first) publish as the DEM's grid:
  // 1080 columns from -179 5/6, wrapping.
  expectSameGrid(cdf->grid(), dem->grid());
  EXPECT_EQ(cdf->grid().cols, 1080);
  EXPECT_TRUE(cdf->grid().wrapsLongitude);
  // Every sample equal: ETOPO20.DEM is the cdf rounded half-to-even (numpy's round); rounding
  // half away from zero would differ in 19696 of the 39318 samples that end in .5.
  EXPECT_EQ(countDifferences(readAll(*cdf), readAll(*dem)), 0u);

  // Independent of the re-centring: look positions up in the raw cdf through GDAL's own
  // geotransform and in the DEM through our grid.
  GDALAllRegister();
  GDALDatasetH raw = GDALOpen((original / "etopo20.cdf").c_str(), GA_ReadOnly);
  ASSERT_NE(raw, nullptr);
  double gt[6];
  ASSERT_EQ(GDALGetGeoTransform(raw, gt), CE_None);
  // Positions inside DEM cells, kept 5% of a cell from their edges: the raw geotransform
  // (step 0.3333333) drifts by up to 1.6e-5 degree across the globe.
  std::mt19937 random(20);
  const geo::SampleGrid& g = dem->grid();
  std::uniform_int_distribution<int64_t> anyCol(0, g.cols - 1), anyRow(0, g.rows - 1);
  std::uniform_real_distribution<double> within(-0.45, 0.45);
  int compared = 0;
  for (int i = 0; i < 400; ++i) {
    int64_t col = anyCol(random);
    const int64_t row = anyRow(random);
    if (i < 40) col = i % 2 ? 0 : g.cols - 1;  // crowd the antimeridian
    const double x = g.firstColumnLongitudeDegrees +
                     (static_cast<double>(col) + within(random)) * g.columnStepDegrees;
    const double y =
        g.firstRowLatitudeDegrees - (static_cast<double>(row) + within(random)) * g.rowStepDegrees;
    int16_t fromDem = 0;
    ASSERT_TRUE(dem->readRow(row, col, 1, &fromDem).ok());
    // Same position in the cdf: longitudes there run from 20 to 380.
    const double cdfX = x < gt[0] ? x + 360 : x;
    const auto px = static_cast<int>(std::floor((cdfX - gt[0]) / gt[1]));
    const auto py = static_cast<int>(std::floor((y - gt[3]) / gt[5]));
    float value = 0;
    ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(raw, 1), GF_Read, px, py, 1, 1, &value, 1, 1,
                           GDT_Float32, 0, 0),
              CE_None);
    EXPECT_EQ(fromDem, static_cast<int16_t>(std::nearbyint(value)))
        << "lon " << x << " lat " << y << " cdf " << value;
    ++compared;
  }
  GDALClose(raw);
  EXPECT_EQ(compared, 400);

  // Reading across the antimeridian from the netCDF source.
  std::vector<int16_t> wrapped(20), direct(1080);
  ASSERT_TRUE(cdf->readRow(270, 1070, 20, wrapped.data()).ok());
  ASSERT_TRUE(cdf->readRow(270, 0, 1080, direct.data()).ok());
  for (size_t i = 0; i < 20; ++i) EXPECT_EQ(wrapped[i], direct[(1070 + i) % 1080]) << i;
}

TEST(GdalSource, NetcdfEtopo60IsAOneDegreeWrappingGrid) {
  GLOBE_REQUIRE_DEM_DIR(original, "original");
  auto cdf = open(original / "etopo60.cdf");
  ASSERT_TRUE(cdf);
  const geo::SampleGrid& g = cdf->grid();
  EXPECT_EQ(g.cols, 360);
  EXPECT_EQ(g.rows, 180);
  EXPECT_TRUE(g.wrapsLongitude);
  EXPECT_EQ(g.firstColumnLongitudeDegrees, -179.5);
  EXPECT_EQ(g.firstRowLatitudeDegrees, 89.5);
  EXPECT_EQ(g.columnStepDegrees, 1.0);
}

TEST(GdalSource, CraterLakeSnapsByAFractionOfACell) {
  // Its step 0.000269965978544 (about 0.97″) is 1/3704.17: within 1e-4 of 1/3704, which moves
  // the far edge of its 429 columns by 0.02 of a cell. Snapped, and placed as GDAL places it.
  GLOBE_REQUIRE_DEM_DIR(original, "original");
  auto tif = open(original / "craterlake-elev-16bit-30m.tif");
  ASSERT_TRUE(tif);
  const geo::SampleGrid& g = tif->grid();
  const double gdalStep = 0.000269965978544;
  EXPECT_EQ(g.cols, 429);
  EXPECT_EQ(g.rows, 279);
  EXPECT_EQ(g.columnStepDegrees, 1.0 / 3704);
  EXPECT_NEAR(g.westDegrees(), -122.165582686187904, 1e-3 * gdalStep);
  EXPECT_NEAR(g.northDegrees(), 42.979451627831743, 1e-3 * gdalStep);
  EXPECT_NEAR(g.eastDegrees(), -122.165582686187904 + 429 * gdalStep, 0.03 * gdalStep);
  EXPECT_NEAR(g.southDegrees(), 42.979451627831743 - 279 * gdalStep, 0.03 * gdalStep);
  EXPECT_FALSE(g.wrapsLongitude);
  // No no-data is declared: its -32767 fill passes through as a (bogus) height.
  std::vector<int16_t> all = readAll(*tif);
  EXPECT_GT(std::count(all.begin(), all.end(), -32767), 0);
}

TEST(GdalSource, ConcurrentReadsAgree) {
  GLOBE_REQUIRE_DEM_DIR(original, "original");
  auto tif = open(original / "mt_fuji_90m.tif");
  ASSERT_TRUE(tif);
  const auto expected = readAll(*tif);
  std::vector<int> bad(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      std::vector<int16_t> row(1201);
      for (int64_t r = t; r < 1201; r += 4) {
        if (!tif->readRow(r, 0, 1201, row.data()).ok() ||
            !std::equal(row.begin(), row.end(), expected.begin() + r * 1201)) {
          ++bad[static_cast<size_t>(t)];
        }
      }
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(bad, std::vector<int>(4, 0));
}

TEST(GdalSource, OutOfRangeReadsAreErrors) {
  GLOBE_REQUIRE_DEM_DIR(original, "original");
  auto tif = open(original / "mt_fuji_90m.tif");
  ASSERT_TRUE(tif);
  int16_t out[4];
  EXPECT_FALSE(tif->readRow(1201, 0, 1, out).ok());
  EXPECT_FALSE(tif->readRow(0, 1200, 2, out).ok());
  EXPECT_FALSE(tif->readRow(0, -1, 1, out).ok());
  auto r = tif->readRow(-1, 0, 1, out);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("mt_fuji_90m.tif: cannot read row -1"), std::string::npos) << r.error();
}

// ---- Synthetic rasters written with GDAL ----

// A one-band GTiff; gt/wkt optional (nullptr / "" leave them out).
template <class T>
void writeTiff(const std::filesystem::path& path, GDALDataType type, int cols, int rows,
               const std::vector<T>& values, const double* gt, const std::string& wkt,
               const double* noData = nullptr) {
  GDALAllRegister();
  GDALDatasetH ds =
      GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), cols, rows, 1, type, nullptr);
  ASSERT_NE(ds, nullptr);
  if (gt) GDALSetGeoTransform(ds, const_cast<double*>(gt));
  if (!wkt.empty()) GDALSetProjection(ds, wkt.c_str());
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  if (noData) GDALSetRasterNoDataValue(band, *noData);
  ASSERT_EQ(GDALRasterIO(band, GF_Write, 0, 0, cols, rows, const_cast<T*>(values.data()), cols,
                         rows, type, 0, 0),
            CE_None);
  GDALClose(ds);
}

TEST(GdalSource, FloatValuesRoundClampAndMapNoData) {
  TempDir tmp;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<float> values = {2.5f, 3.5f, -2.5f, 1.49f, -7.6f,  nan,
                                     inf,  -inf, 1e6f,  -1e6f, -500.f, 8848.4f};
  const double gt[6] = {10, 0.5, 0, 50, 0, -0.5};
  const double noData = -500;
  writeTiff(tmp / "f.tif", GDT_Float32, 6, 2, values, gt, globe::testing::wktOfEpsg(4326), &noData);
  auto s = open(tmp / "f.tif");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->grid().firstColumnLongitudeDegrees, 10.25);
  EXPECT_EQ(s->grid().firstRowLatitudeDegrees, 49.75);
  const auto all = readAll(*s);
  EXPECT_EQ(all, (std::vector<int16_t>{2, 4, -2, 1, -8, -9999, -9999, -9999, 32767, -32768, -9999,
                                       8848}));
}

TEST(GdalSource, BottomUpRowsAreFlippedToNorthFirst) {
  TempDir tmp;
  const std::vector<int16_t> values = {1, 2, 3, 4, 5, 6};  // dataset row 0 is the south
  const double gt[6] = {10, 1, 0, 40, 0, 1};
  writeTiff(tmp / "up.tif", GDT_Int16, 2, 3, values, gt, globe::testing::wktOfEpsg(4326));
  auto s = open(tmp / "up.tif");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->grid().firstRowLatitudeDegrees, 42.5);
  EXPECT_EQ(s->grid().rowStepDegrees, 1.0);
  EXPECT_EQ(s->grid().southDegrees(), 40.0);
  EXPECT_EQ(readAll(*s), (std::vector<int16_t>{5, 6, 3, 4, 1, 2}));
}

TEST(GdalSource, ProjectedRasterIsWarpedToDegrees) {
  // UTM 32N, 100 m pixels around 4.9°E 50°N, heights a linear ramp (100 per column, 150 per row)
  // that bilinear resampling nearly reproduces: geolocation errors show up in the values.
  TempDir tmp;
  const int n = 100;
  std::vector<int16_t> values(n * n);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c)
      values[static_cast<size_t>(r * n + c)] = static_cast<int16_t>(100 * c + 150 * r);
  }
  const double e0 = 200000, n0 = 5545000, pixel = 100;  // 4.2° west of the zone's meridian
  const double gt[6] = {e0, pixel, 0, n0, 0, -pixel};
  writeTiff(tmp / "utm.tif", GDT_Int16, n, n, values, gt, globe::testing::wktOfEpsg(32632));
  auto s = open(tmp / "utm.tif");
  ASSERT_TRUE(s);
  const geo::SampleGrid& g = s->grid();
  EXPECT_NEAR(g.westDegrees(), 4.8149, 0.002);  // corners from gdaltransform
  EXPECT_NEAR(g.northDegrees(), 49.9867, 0.002);
  EXPECT_NEAR(g.eastDegrees(), 4.9616, 0.002);
  EXPECT_NEAR(g.southDegrees(), 49.8920, 0.002);
  EXPECT_GT(g.cols, 100);
  EXPECT_LT(g.columnStepDegrees, 0.01);

  OGRSpatialReferenceH wgs84 = OSRNewSpatialReference(nullptr),
                       utm = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(wgs84, 4326);
  OSRImportFromEPSG(utm, 32632);
  OSRSetAxisMappingStrategy(wgs84, OAMS_TRADITIONAL_GIS_ORDER);
  OSRSetAxisMappingStrategy(utm, OAMS_TRADITIONAL_GIS_ORDER);
  OGRCoordinateTransformationH toUtm = OCTNewCoordinateTransformation(wgs84, utm);
  ASSERT_NE(toUtm, nullptr);
  int inside = 0, outside = 0;
  double worst = 0, sum = 0;
  std::vector<int16_t> row(static_cast<size_t>(g.cols));
  for (int64_t r = 0; r < g.rows; ++r) {
    ASSERT_TRUE(s->readRow(r, 0, g.cols, row.data()).ok());
    for (int64_t c = 0; c < g.cols; ++c) {
      double x = g.firstColumnLongitudeDegrees + static_cast<double>(c) * g.columnStepDegrees;
      double y = g.firstRowLatitudeDegrees - static_cast<double>(r) * g.rowStepDegrees;
      ASSERT_TRUE(OCTTransform(toUtm, 1, &x, &y, nullptr));
      const double px = (x - e0) / pixel, py = (n0 - y) / pixel;  // source pixel coordinates
      const int16_t v = row[static_cast<size_t>(c)];
      // Away from the source's edges: there the warper's kernel is cut short and biased.
      if (px > 3 && px < n - 3 && py > 3 && py < n - 3) {
        ++inside;
        const double residual = v - (100 * (px - 0.5) + 150 * (py - 0.5));
        worst = std::max(worst, std::abs(residual));
        sum += residual;
      } else if (px < -1 || px > n + 1 || py < -1 || py > n + 1) {
        ++outside;
        ASSERT_EQ(v, kNoDataHeight) << "row " << r << " col " << c;  // not 0 m
      }
    }
  }
  OCTDestroyCoordinateTransformation(toUtm);
  OSRDestroySpatialReference(wgs84);
  OSRDestroySpatialReference(utm);
  EXPECT_GT(inside, 5000);
  // No systematic shift (half a pixel, the corner/centre mistake, would be 50 to 75); single
  // values stray by GDAL's widened bilinear kernel (dst cells are 1.3 source pixels tall here).
  EXPECT_LT(std::abs(sum / inside), 1.0);
  EXPECT_LT(worst, 30.0);
  EXPECT_GT(outside, 100);  // the UTM square is turned 3° against the meridians
}

TEST(GdalSource, GeoreferenceProblemsAreErrors) {
  TempDir tmp;
  const std::vector<int16_t> values(4, 1);
  const double rotated[6] = {10, 1, 0.1, 40, 0, -1};
  writeTiff(tmp / "rot.tif", GDT_Int16, 2, 2, values, rotated, globe::testing::wktOfEpsg(4326));
  writeTiff(tmp / "plain.tif", GDT_Int16, 2, 2, values, nullptr, "");
  const double metres[6] = {500000, 30, 0, 5500000, 0, -30};
  writeTiff(tmp / "nocrs.tif", GDT_Int16, 2, 2, values, metres, "");
  const double degrees[6] = {-10, 1, 0, 40, 0, -1};
  writeTiff(tmp / "degrees.tif", GDT_Int16, 2, 2, values, degrees, "");

  for (auto [name, needle] :
       {std::pair{"rot.tif", "rotated geotransforms are not supported"},
        {"plain.tif", "has no geotransform"},
        {"nocrs.tif", "has no coordinate system and its geotransform is not in degrees"}}) {
    auto s = openRasterSource(tmp / name);
    ASSERT_FALSE(s.ok()) << name;
    EXPECT_NE(s.error().find((tmp / name).string() + ": " + needle), std::string::npos)
        << s.error();
  }
  auto plausible = openRasterSource(tmp / "degrees.tif");
  ASSERT_TRUE(plausible.ok()) << plausible.error();
  EXPECT_EQ((*plausible)->grid().firstColumnLongitudeDegrees, -9.5);
}

TEST(GdalSource, NotARasterIsAnError) {
  TempDir tmp;
  globe::testing::writeText(tmp / "notes.txt", "These are not the heights you are looking for.\n");
  for (auto* opener : {&openGdalSource, &openRasterSource}) {
    auto s = opener(tmp / "notes.txt", {});
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().find((tmp / "notes.txt").string() + ": GDAL cannot open it as a raster"),
              std::string::npos)
        << s.error();
  }
  auto missing = openRasterSource(tmp / "missing.tif");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error(), (tmp / "missing.tif").string() + ": no such file");
  auto dir = openRasterSource(tmp.path());
  ASSERT_FALSE(dir.ok());
  EXPECT_NE(dir.error().find(tmp.path().string() + ": GDAL cannot open it as a raster"),
            std::string::npos)
      << dir.error();
}

}  // namespace
}  // namespace globe::rasters
