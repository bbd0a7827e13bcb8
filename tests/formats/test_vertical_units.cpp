// Vertical units: the unit names GDAL files state, overrides, what GdalSource and the GTOPO30
// reader make of them (no-data tested on the stored value, warped rasters), and the manifest's
// record of it.
#include <cpl_conv.h>
#include <gdal.h>
#include <gtest/gtest.h>
#include <ogr_srs_api.h>

#include <cmath>
#include <string>
#include <vector>

#include "formats/pyramid_manifest.hpp"
#include "formats/vertical_units.hpp"
#include "rasters/raster_source.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/epsg_wkt.hpp"
#include "tests/support/test_io_util.hpp"

namespace globe::formats {
namespace {

using globe::testing::TempDir;

constexpr double kUsSurveyFoot = 1200.0 / 3937.0;

TEST(VerticalUnits, KnownNamesInAnyCase) {
  for (const char* metres : {"", " ", "m", "M", "metre", "Meter", "metres", "METERS"}) {
    EXPECT_EQ(metersPerUnitNamed(metres), 1.0) << metres;
  }
  for (const char* feet : {"ft", "FT", "foot", "Feet", "international foot", " ft "}) {
    EXPECT_EQ(metersPerUnitNamed(feet), 0.3048) << feet;
  }
  for (const char* survey : {"US survey foot", "us survey foot", "ftUS", "us-ft", "Foot_US"}) {
    EXPECT_EQ(metersPerUnitNamed(survey), kUsSurveyFoot) << survey;
  }
  for (const char* unknown : {"furlong", "km", "fathom", "mm", "feet above sea"}) {
    EXPECT_FALSE(metersPerUnitNamed(unknown)) << unknown;
  }
}

TEST(VerticalUnits, OverridesApplyWhereNoKnownUnitIsStatedAndUnknownUnitsAreErrors) {
  auto file = resolveVerticalUnits("x.tif", "ft", 1, 0, {});
  ASSERT_TRUE(file) << file.error();
  EXPECT_EQ(file->origin, VerticalUnitOrigin::File);
  EXPECT_EQ(file->metersPerUnit, 0.3048);
  EXPECT_EQ(describe(*file), "unit \"ft\" -> x0.3048 m");

  auto none = resolveVerticalUnits("x.tif", "", 1, 0, {});
  ASSERT_TRUE(none) << none.error();
  EXPECT_EQ(none->origin, VerticalUnitOrigin::Default);
  EXPECT_TRUE(none->isIdentity());
  EXPECT_EQ(describe(*none), "no unit (metres) -> x1 m");

  auto unknown = resolveVerticalUnits("x.tif", "furlong", 1, 0, {});
  ASSERT_FALSE(unknown);
  EXPECT_EQ(
      unknown.error(),
      "x.tif: unknown vertical unit 'furlong'; give --z-units m|ft|us-ft or --z-scale FACTOR");

  VerticalOverride zUnits;
  zUnits.units = "us-ft";
  auto overridden = resolveVerticalUnits("x.tif", "furlong", 0.5, 3000, zUnits);
  ASSERT_TRUE(overridden) << overridden.error();
  EXPECT_EQ(overridden->origin, VerticalUnitOrigin::ZUnits);
  EXPECT_EQ(overridden->metersPerUnit, kUsSurveyFoot);
  EXPECT_DOUBLE_EQ(overridden->toMeters(100), (100 * 0.5 + 3000) * kUsSurveyFoot);
  EXPECT_EQ(describe(*overridden),
            "--z-units us-ft (file unit \"furlong\") -> x0.3048006096 m, after band scale 0.5 "
            "and offset 3000");

  VerticalOverride zScale;
  zScale.metersPerUnit = 2;
  zScale.units = "ft";  // --z-scale wins over --z-units
  auto scaled = resolveVerticalUnits("x.tif", "", 1, 0, zScale);
  ASSERT_TRUE(scaled) << scaled.error();
  EXPECT_EQ(scaled->origin, VerticalUnitOrigin::ZScale);
  EXPECT_EQ(scaled->metersPerUnit, 2.0);

  // A unit the file or the format states is kept: the overrides are for the inputs without one.
  auto stated = resolveVerticalUnits("x.tif", "m", 1, 0, zScale);
  ASSERT_TRUE(stated) << stated.error();
  EXPECT_EQ(stated->origin, VerticalUnitOrigin::File);
  EXPECT_EQ(stated->metersPerUnit, 1.0);
  auto format = resolveVerticalUnits("x.DEM", "m", 1, 0, zScale, /*formatIsMeters=*/true);
  ASSERT_TRUE(format);
  EXPECT_EQ(format->origin, VerticalUnitOrigin::Format);
  EXPECT_TRUE(format->isIdentity());

  VerticalOverride badUnits;
  badUnits.units = "furlong";
  EXPECT_FALSE(checkVerticalOverride(badUnits));
  for (double bad : {0.0, std::nan(""), HUGE_VAL}) {
    VerticalOverride badScale;
    badScale.metersPerUnit = bad;
    EXPECT_FALSE(checkVerticalOverride(badScale)) << bad;
  }
  EXPECT_FALSE(resolveVerticalUnits("x.tif", "m", 0, 0, {}));  // a zero band scale
}

struct BandUnits {
  const char* unit = nullptr;
  double scale = 1, offset = 0;
};

// A one-band GTiff of int16 values with no data -32768 and the given unit, scale and offset.
void writeUnitTiff(const std::filesystem::path& path, int cols, int rows,
                   const std::vector<int16_t>& values, const double gt[6], int epsg,
                   const BandUnits& units) {
  GDALAllRegister();
  GDALDatasetH ds =
      GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), cols, rows, 1, GDT_Int16, nullptr);
  ASSERT_NE(ds, nullptr);
  GDALSetGeoTransform(ds, const_cast<double*>(gt));
  GDALSetProjection(ds, globe::testing::wktOfEpsg(epsg).c_str());
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  GDALSetRasterNoDataValue(band, -32768);
  if (units.unit) GDALSetRasterUnitType(band, units.unit);
  if (units.scale != 1) GDALSetRasterScale(band, units.scale);
  if (units.offset != 0) GDALSetRasterOffset(band, units.offset);
  ASSERT_EQ(GDALRasterIO(band, GF_Write, 0, 0, cols, rows, const_cast<int16_t*>(values.data()),
                         cols, rows, GDT_Int16, 0, 0),
            CE_None);
  GDALClose(ds);
}

std::vector<int16_t> readEverySample(const rasters::RasterSource& s) {
  const geo::SampleGrid& g = s.grid();
  std::vector<int16_t> all(static_cast<size_t>(g.cols * g.rows));
  for (int64_t r = 0; r < g.rows; ++r) {
    auto ok = s.readRow(r, 0, g.cols, all.data() + r * g.cols);
    EXPECT_TRUE(ok.ok()) << ok.error();
  }
  return all;
}

TEST(VerticalUnits, GdalScaleOffsetAndUnitBeforeRoundingNoDataOnTheStoredValue) {
  TempDir tmp;
  // feet = stored * 0.5 + 3000; -32768 is no data although it would scale to -4079 m.
  const std::vector<int16_t> values = {0, 1000, -32768, 12976, -6000, 1};
  const double gt[6] = {10, 0.5, 0, 50, 0, -0.5};
  writeUnitTiff(tmp / "ft.tif", 3, 2, values, gt, 4326, {"ft", 0.5, 3000});
  auto source = rasters::openRasterSource(tmp / "ft.tif");
  ASSERT_TRUE(source) << source.error();
  EXPECT_EQ(describe((*source)->verticalUnits()),
            "unit \"ft\" -> x0.3048 m, after band scale 0.5 and offset 3000");
  // 3000 ft = 914.4; 3500 ft = 1066.8; 9488 ft = 2891.94; 0 ft = 0; 3000.5 ft = 914.55.
  EXPECT_EQ(readEverySample(**source), (std::vector<int16_t>{914, 1067, -9999, 2892, 0, 915}));

  // The same file with --z-units m: its stated unit is kept (the override is for inputs that
  // state none).
  rasters::RasterOpenOptions metres;
  metres.vertical.units = "m";
  auto kept = rasters::openRasterSource(tmp / "ft.tif", metres);
  ASSERT_TRUE(kept) << kept.error();
  EXPECT_EQ(readEverySample(**kept), (std::vector<int16_t>{914, 1067, -9999, 2892, 0, 915}));

  // Without a stated unit, --z-units m gives it: the scale and offset kept.
  writeUnitTiff(tmp / "bare.tif", 3, 2, values, gt, 4326, {nullptr, 0.5, 3000});
  auto overridden = rasters::openRasterSource(tmp / "bare.tif", metres);
  ASSERT_TRUE(overridden) << overridden.error();
  EXPECT_EQ(readEverySample(**overridden),
            (std::vector<int16_t>{3000, 3500, -9999, 9488, 0, 3000}));

  writeUnitTiff(tmp / "furlong.tif", 3, 2, values, gt, 4326, {"furlong"});
  auto unknown = rasters::openGdalSource(tmp / "furlong.tif");
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.error(), (tmp / "furlong.tif").string() +
                                 ": unknown vertical unit 'furlong'; give --z-units m|ft|us-ft "
                                 "or --z-scale FACTOR");
}

TEST(VerticalUnits, WarpedRastersKeepTheSourceBandsUnit) {
  TempDir tmp;
  // UTM 32N, 100 m pixels, 1000 US survey feet everywhere (304.8 m).
  const std::vector<int16_t> values(40 * 40, 1000);
  const double gt[6] = {350000, 100, 0, 5540000, 0, -100};
  writeUnitTiff(tmp / "utm.tif", 40, 40, values, gt, 32632, {"US survey foot"});
  auto source = rasters::openRasterSource(tmp / "utm.tif");
  ASSERT_TRUE(source) << source.error();
  EXPECT_EQ((*source)->verticalUnits().metersPerUnit, kUsSurveyFoot);
  size_t land = 0;
  for (int16_t h : readEverySample(**source)) {
    if (h == -9999) continue;  // outside the warped footprint
    EXPECT_EQ(h, 305);
    ++land;
  }
  EXPECT_GT(land, 1000u);
}

TEST(VerticalUnits, Gtopo30StaysMetresWhateverTheOverride) {
  // GTOPO30 is metres by definition: a --z-units meant for another input leaves it alone.
  const auto dem = std::filesystem::path(GLOBE_SOURCE_DIR) / "data/dem/E138N35_FUJI.DEM";
  auto metres = rasters::openGtopo30Source(dem);
  ASSERT_TRUE(metres) << metres.error();
  EXPECT_EQ((*metres)->verticalUnits().origin, VerticalUnitOrigin::Format);
  EXPECT_EQ(describe((*metres)->verticalUnits()), "metres by format -> x1 m");
  rasters::RasterOpenOptions feet;
  feet.vertical.units = "ft";
  auto kept = rasters::openRasterSource(dem, feet);
  ASSERT_TRUE(kept) << kept.error();
  EXPECT_EQ((*kept)->verticalUnits().origin, VerticalUnitOrigin::Format);
  const int64_t cols = (*metres)->grid().cols;
  std::vector<int16_t> a(static_cast<size_t>(cols)), b(a.size());
  const int64_t row = (*metres)->grid().rows / 2;
  ASSERT_TRUE((*metres)->readRow(row, 0, cols, a.data()));
  ASSERT_TRUE((*kept)->readRow(row, 0, cols, b.data()));
  EXPECT_EQ(a, b);
}

PyramidManifest manifestWithOneSource() {
  PyramidManifest m;
  m.levels.push_back({0, 2, {-180, -90, 180, 90}, {0, 100}, {{0, 0, 0}}});
  SourceInfo s;
  s.path = "x.tif";
  s.format = "GTiff";
  s.columns = s.rows = 10;
  s.stepDegrees = 0.1;
  s.bounds = {0, 0, 1, 1};
  m.sources.push_back(s);
  return m;
}

TEST(VerticalUnits, ManifestRecordsThemAndReadsManifestsWithout) {
  PyramidManifest m = manifestWithOneSource();
  VerticalOverride zUnits;
  zUnits.units = "us-ft";
  auto units = resolveVerticalUnits("x.tif", "", 0.5, 3000, zUnits);
  ASSERT_TRUE(units);
  m.sources[0].verticalUnits = *units;
  const std::string text = manifestToJson(m);
  EXPECT_NE(text.find("\"description\": \"--z-units us-ft (file unit none)"), std::string::npos)
      << text;
  auto back = manifestFromJson(text, "manifest.json");
  ASSERT_TRUE(back) << back.error();
  ASSERT_TRUE(back->sources[0].verticalUnits);
  EXPECT_EQ(*back->sources[0].verticalUnits, *units);

  // Written before units were recorded: read, with nothing claimed.
  m.sources[0].verticalUnits.reset();
  const std::string old = manifestToJson(m);
  EXPECT_EQ(old.find("verticalUnits"), std::string::npos);
  auto oldBack = manifestFromJson(old, "manifest.json");
  ASSERT_TRUE(oldBack) << oldBack.error();
  EXPECT_FALSE(oldBack->sources[0].verticalUnits);

  std::string bad = text;
  bad.replace(bad.find("\"--z-units\""), 11, "\"guess\"");
  auto refused = manifestFromJson(bad, "manifest.json");
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("appliedBy"), std::string::npos) << refused.error();
}

}  // namespace
}  // namespace globe::formats
