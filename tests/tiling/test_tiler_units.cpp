// Vertical units of elevation inputs, through the real globe-tiler: Zion (SRTM 3", metres) stored
// in feet, US survey feet, or int16 with a band scale and offset is drawn as the metre original;
// --z-units / --z-scale give the unit of inputs that state none; an unknown unit and a raster
// without one 2x2 cell of valid samples are refused naming the file; the manifest and `globe info`
// say what was read.
#include <gdal.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "terrain/height_block.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "transport/atomic_file.hpp"

namespace globe::tiling {
namespace {

namespace fs = std::filesystem;

constexpr double kFootMeters = 0.3048;
constexpr double kUsSurveyFootMeters = 1200.0 / 3937.0;

struct UnitsRaster {
  int cols = 0, rows = 0;
  std::array<double, 6> geoTransform{};
  std::string wkt;
  std::vector<double> meters;  // NaN: no data
};

UnitsRaster readRaster(const fs::path& path) {
  GDALAllRegister();
  UnitsRaster r;
  GDALDatasetH ds = GDALOpen(path.c_str(), GA_ReadOnly);
  EXPECT_NE(ds, nullptr) << path;
  if (!ds) return r;
  r.cols = GDALGetRasterXSize(ds);
  r.rows = GDALGetRasterYSize(ds);
  GDALGetGeoTransform(ds, r.geoTransform.data());
  r.wkt = GDALGetProjectionRef(ds);
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  r.meters.resize(static_cast<size_t>(r.cols) * static_cast<size_t>(r.rows));
  EXPECT_EQ(GDALRasterIO(band, GF_Read, 0, 0, r.cols, r.rows, r.meters.data(), r.cols, r.rows,
                         GDT_Float64, 0, 0),
            CE_None);
  int hasNoData = 0;
  const double noData = GDALGetRasterNoDataValue(band, &hasNoData);
  for (double& v : r.meters) {
    if (hasNoData && v == noData) v = std::nan("");
  }
  GDALClose(ds);
  return r;
}

// Zion Canyon, SRTM 3" in metres: what every encoded copy must be drawn as.
const UnitsRaster& zion() {
  static const UnitsRaster raster =
      readRaster(fs::path(GLOBE_SOURCE_DIR) / "data/dem/zion-srtm3.tif");
  return raster;
}

// How a copy stores its heights: stored = (metres / metersPerUnit - offset) / scale.
struct Encoding {
  GDALDataType type = GDT_Float32;
  std::optional<std::string> unit;  // unset: the file states none
  double metersPerUnit = 1;
  double scale = 1, offset = 0;
  double noData = -32768;
};

void writeRaster(const fs::path& path, const UnitsRaster& r, const Encoding& e) {
  GDALAllRegister();
  GDALDatasetH ds =
      GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), r.cols, r.rows, 1, e.type, nullptr);
  ASSERT_NE(ds, nullptr) << path;
  std::array<double, 6> gt = r.geoTransform;
  GDALSetGeoTransform(ds, gt.data());
  GDALSetProjection(ds, r.wkt.c_str());
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  GDALSetRasterNoDataValue(band, e.noData);
  if (e.unit) GDALSetRasterUnitType(band, e.unit->c_str());
  if (e.scale != 1) GDALSetRasterScale(band, e.scale);
  if (e.offset != 0) GDALSetRasterOffset(band, e.offset);
  std::vector<double> stored(r.meters.size());
  const bool integer = e.type != GDT_Float32 && e.type != GDT_Float64;
  for (size_t i = 0; i < stored.size(); ++i) {
    const double v = (r.meters[i] / e.metersPerUnit - e.offset) / e.scale;
    stored[i] = std::isnan(r.meters[i]) ? e.noData : integer ? std::nearbyint(v) : v;
  }
  ASSERT_EQ(GDALRasterIO(band, GF_Write, 0, 0, r.cols, r.rows, stored.data(), r.cols, r.rows,
                         GDT_Float64, 0, 0),
            CE_None);
  GDALClose(ds);
}

// A small raster in degrees near Zion: `meters` row by row, NaN as no data.
UnitsRaster smallRaster(int cols, int rows, std::vector<double> meters) {
  UnitsRaster r;
  r.cols = cols;
  r.rows = rows;
  r.geoTransform = {-113.0, 0.01, 0, 37.3, 0, -0.01};
  r.wkt = zion().wkt;
  r.meters = std::move(meters);
  return r;
}

struct ProgramRun {
  int exitCode = -1;
  std::string output;  // stdout and stderr
};

ProgramRun runUnitsProgram(const std::string& exe, const std::vector<std::string>& arguments) {
  std::string command = exe;
  for (const std::string& a : arguments) command += " '" + a + "'";
  command += " 2>&1";
  ProgramRun run;
  FILE* pipe = ::popen(command.c_str(), "r");
  std::array<char, 4096> buffer{};
  while (pipe != nullptr && std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) {
    run.output += buffer.data();
  }
  const int status = pipe != nullptr ? ::pclose(pipe) : -1;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

ProgramRun runGlobeTiler(const fs::path& pyramid, const std::vector<std::string>& inputs,
                         const std::vector<std::string>& options = {}) {
  std::vector<std::string> arguments = {"-q", "-o", pyramid.string()};
  arguments.insert(arguments.end(), inputs.begin(), inputs.end());
  arguments.insert(arguments.end(), options.begin(), options.end());
  return runUnitsProgram(GLOBE_TILER_EXE, arguments);
}

// Every block of every level, as the viewer reads them.
std::map<geo::TileId, std::vector<int16_t>> readBlocks(const fs::path& pyramid) {
  std::map<geo::TileId, std::vector<int16_t>> blocks;
  auto manifest = formats::readManifest(pyramid);
  EXPECT_TRUE(manifest) << manifest.error();
  if (!manifest) return blocks;
  for (const formats::LevelInfo& level : manifest->levels) {
    for (const formats::PackId& id : level.packs) {
      const auto path = formats::packPath(pyramid, id);
      auto bytes = transport::readWholeFile(path, 1ULL << 32);
      EXPECT_TRUE(bytes) << bytes.error();
      if (!bytes) continue;
      auto pack = formats::decodePack(*bytes, path);
      EXPECT_TRUE(pack) << pack.error();
      if (!pack) continue;
      for (size_t slot = 0; slot < pack->entries.size(); ++slot) {
        if (!pack->entries[slot].present()) continue;
        const auto block = pack->block(slot);
        blocks[formats::tileOfSlot(id, slot, pack->layout.tilesPerSide)] = {block.begin(),
                                                                            block.end()};
      }
    }
  }
  return blocks;
}

// Tiles `inputs` (with `options`) into dir/name; a failure is a test failure.
fs::path tileOk(const fs::path& dir, const std::string& name,
                const std::vector<std::string>& inputs,
                const std::vector<std::string>& options = {}) {
  const fs::path pyramid = dir / name;
  const ProgramRun run = runGlobeTiler(pyramid, inputs, options);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  return pyramid;
}

const fs::path& workDir() {
  static const fs::path dir = globe::testing::freshTempDir("tiler-units");
  return dir;
}

// The metre original tiled as it is: the surface every encoded copy must draw.
const std::map<geo::TileId, std::vector<int16_t>>& metreBlocks() {
  static const auto blocks = [] {
    return readBlocks(
        tileOk(workDir(), "metres", {std::string(GLOBE_SOURCE_DIR) + "/data/dem/zion-srtm3.tif"}));
  }();
  return blocks;
}

// Largest |drawn - metre original| over every vertex of every block (same tiles required).
double largestDifferenceMeters(const std::map<geo::TileId, std::vector<int16_t>>& blocks) {
  const auto& reference = metreBlocks();
  EXPECT_EQ(blocks.size(), reference.size());
  EXPECT_GT(reference.size(), 100u);
  double largest = 0;
  for (const auto& [tile, samples] : reference) {
    auto it = blocks.find(tile);
    if (it == blocks.end()) {
      ADD_FAILURE() << "tile " << tile.level << "/" << tile.x << "/" << tile.y << " missing";
      return INFINITY;
    }
    for (size_t i = 0; i < samples.size(); ++i) {
      largest = std::max(largest, std::abs(terrain::surfaceHeightMeters(it->second[i]) -
                                           terrain::surfaceHeightMeters(samples[i])));
    }
  }
  return largest;
}

double drawnAsMetreOriginal(const std::string& name, const Encoding& encoding,
                            const std::vector<std::string>& options = {}) {
  const fs::path tif = workDir() / (name + ".tif");
  writeRaster(tif, zion(), encoding);
  return largestDifferenceMeters(readBlocks(tileOk(workDir(), name, {tif.string()}, options)));
}

TEST(TilerUnits, FeetAreDrawnAsTheMetreOriginal) {
  Encoding feet;
  feet.unit = "ft";
  feet.metersPerUnit = kFootMeters;
  EXPECT_LE(drawnAsMetreOriginal("feet", feet), 1.0);
  Encoding foot = feet;
  foot.unit = "Foot";  // case does not matter
  EXPECT_LE(drawnAsMetreOriginal("foot", foot), 1.0);
}

TEST(TilerUnits, UsSurveyFeetAreDrawnAsTheMetreOriginal) {
  Encoding survey;
  survey.unit = "US survey foot";
  survey.metersPerUnit = kUsSurveyFootMeters;
  EXPECT_LE(drawnAsMetreOriginal("us-survey-feet", survey), 1.0);
}

TEST(TilerUnits, BandScaleAndOffsetApplyBeforeTheUnit) {
  // int16 half-feet above 3,000 ft: feet = stored * 0.5 + 3000.
  Encoding scaled;
  scaled.type = GDT_Int16;
  scaled.unit = "ft";
  scaled.metersPerUnit = kFootMeters;
  scaled.scale = 0.5;
  scaled.offset = 3000;
  EXPECT_LE(drawnAsMetreOriginal("scaled-int16", scaled), 1.0);
}

TEST(TilerUnits, ZUnitsAndZScaleApplyToInputsThatStateNoUnit) {
  Encoding unitless;  // feet, but the file states no unit (metres by default)
  unitless.metersPerUnit = kFootMeters;
  EXPECT_LE(drawnAsMetreOriginal("z-units-ft", unitless, {"--z-units", "ft"}), 1.0);
  EXPECT_LE(drawnAsMetreOriginal("z-scale", unitless, {"--z-scale", "0.3048"}), 1.0);

  Encoding usFeet;  // US survey feet, no unit stated
  usFeet.metersPerUnit = kUsSurveyFootMeters;
  EXPECT_LE(drawnAsMetreOriginal("z-units-us-ft", usFeet, {"--z-units", "us-ft"}), 1.0);

  // A unit the file states is kept: the overrides are for inputs that state none. (With a
  // 20′ base grid beside it, --z-units ft must not shrink the base.)
  Encoding stated;
  stated.unit = "ft";
  stated.metersPerUnit = kFootMeters;
  EXPECT_LE(drawnAsMetreOriginal("z-units-stated", stated, {"--z-units", "us-ft"}), 1.0);

  Encoding unknown;  // an unknown unit is fine once overridden
  unknown.unit = "furlong";
  unknown.metersPerUnit = kFootMeters;
  EXPECT_LE(drawnAsMetreOriginal("z-scale-unknown", unknown, {"--z-scale", "0.3048"}), 1.0);
}

TEST(TilerUnits, ABaseGridTiledBesideKeepsItsMetres) {
  // The usual command: a feet DEM without a unit over the 20′ world grid, --z-units ft. The grid
  // (GTOPO30: metres by definition) keeps its heights, and the tiler says so.
  Encoding feet;
  feet.metersPerUnit = kFootMeters;
  const fs::path tif = workDir() / "base-feet.tif";
  writeRaster(tif, zion(), feet);
  const std::string world = std::string(GLOBE_SOURCE_DIR) + "/data/dem/ETOPO20.DEM";
  const ProgramRun run =
      runGlobeTiler(workDir() / "base-beside", {world, tif.string()}, {"--z-units", "ft"});
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("ETOPO20.DEM: keeps its own unit (metres by format -> x1 m)"),
            std::string::npos)
      << run.output;
  auto manifest = formats::readManifest(workDir() / "base-beside");
  ASSERT_TRUE(manifest) << manifest.error();
  for (const formats::SourceInfo& source : manifest->sources) {
    ASSERT_TRUE(source.verticalUnits);
    const bool isWorld = source.path == world;
    EXPECT_EQ(source.verticalUnits->origin,
              isWorld ? formats::VerticalUnitOrigin::Format : formats::VerticalUnitOrigin::ZUnits);
    EXPECT_EQ(source.verticalUnits->metersPerUnit, isWorld ? 1.0 : kFootMeters);
  }
}

TEST(TilerUnits, UnknownUnitIsAnErrorNamingTheFile) {
  Encoding furlong;
  furlong.unit = "furlong";
  const fs::path tif = workDir() / "furlong.tif";
  writeRaster(tif, zion(), furlong);
  const ProgramRun run = runGlobeTiler(workDir() / "furlong", {tif.string()});
  EXPECT_EQ(run.exitCode, 1) << run.output;
  EXPECT_NE(run.output.find(tif.string() + ": unknown vertical unit 'furlong'; give --z-units "
                                           "m|ft|us-ft or --z-scale FACTOR"),
            std::string::npos)
      << run.output;
  EXPECT_FALSE(fs::exists(workDir() / "furlong" / formats::kManifestFileName));
}

TEST(TilerUnits, BadOverridesAreErrors) {
  const std::string tif = std::string(GLOBE_SOURCE_DIR) + "/data/dem/zion-srtm3.tif";
  const ProgramRun furlong =
      runGlobeTiler(workDir() / "bad-z-units", {tif}, {"--z-units", "furlong"});
  EXPECT_EQ(furlong.exitCode, 1) << furlong.output;
  EXPECT_NE(furlong.output.find("--z-units must be m, ft or us-ft, not 'furlong'"),
            std::string::npos)
      << furlong.output;
  const ProgramRun zero = runGlobeTiler(workDir() / "bad-z-scale", {tif}, {"--z-scale", "0"});
  EXPECT_EQ(zero.exitCode, 1) << zero.output;
  EXPECT_NE(zero.output.find("--z-scale must be"), std::string::npos) << zero.output;
  const ProgramRun both =
      runGlobeTiler(workDir() / "both", {tif}, {"--z-units", "ft", "--z-scale", "0.3048"});
  EXPECT_NE(both.exitCode, 0) << both.output;
  EXPECT_NE(both.output.find("excludes"), std::string::npos) << both.output;
}

// A colour photo's red band is not elevation: refused, naming the bands and the imagery tiler;
// tiled as heights only when told --force.
TEST(TilerUnits, AColourImageIsRefusedAsElevationUnlessForced) {
  const std::string tif = std::string(GLOBE_SOURCE_DIR) + "/data/imagery/zion-landsat8-rgb.tif";
  const ProgramRun refused = runGlobeTiler(workDir() / "photo", {tif});
  EXPECT_EQ(refused.exitCode, 1) << refused.output;
  EXPECT_NE(refused.output.find(tif + ": an 8-bit colour image (bands 1 red, 2 green, 3 blue), "
                                      "not elevation: tile it as a layer with `globe-tiler "
                                      "imagery`, or give --force"),
            std::string::npos)
      << refused.output;
  EXPECT_FALSE(fs::exists(workDir() / "photo" / formats::kManifestFileName));
  const ProgramRun forced = runGlobeTiler(workDir() / "photo-forced", {tif}, {"--force"});
  EXPECT_EQ(forced.exitCode, 0) << forced.output;
  EXPECT_TRUE(fs::exists(workDir() / "photo-forced" / formats::kManifestFileName));
}

TEST(TilerUnits, HelpListsTheOptions) {
  const ProgramRun help = runUnitsProgram(GLOBE_TILER_EXE, {"--help"});
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.output.find("--z-units"), std::string::npos) << help.output;
  EXPECT_NE(help.output.find("m | ft | us-ft"), std::string::npos) << help.output;
  EXPECT_NE(help.output.find("--z-scale"), std::string::npos) << help.output;
  EXPECT_NE(help.output.find("metres per stored unit"), std::string::npos) << help.output;
}

TEST(TilerUnits, ManifestAndInfoSayWhatWasRead) {
  Encoding feet;
  feet.unit = "ft";
  feet.metersPerUnit = kFootMeters;
  const fs::path tif = workDir() / "info-feet.tif";
  writeRaster(tif, zion(), feet);
  const fs::path pyramid = tileOk(workDir(), "info-feet", {tif.string()});
  auto manifest = formats::readManifest(pyramid);
  ASSERT_TRUE(manifest) << manifest.error();
  ASSERT_EQ(manifest->sources.size(), 1u);
  ASSERT_TRUE(manifest->sources[0].verticalUnits);
  const formats::VerticalUnits& units = *manifest->sources[0].verticalUnits;
  EXPECT_EQ(units.fileUnit, "ft");
  EXPECT_EQ(units.origin, formats::VerticalUnitOrigin::File);
  EXPECT_EQ(units.metersPerUnit, kFootMeters);

  const ProgramRun text = runUnitsProgram(GLOBE_EXE, {"info", pyramid.string()});
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_NE(text.output.find("heights unit \"ft\" -> x0.3048 m"), std::string::npos) << text.output;
  const ProgramRun json = runUnitsProgram(GLOBE_EXE, {"info", "--json", pyramid.string()});
  ASSERT_EQ(json.exitCode, 0) << json.output;
  const auto j = nlohmann::json::parse(json.output);
  EXPECT_EQ(j["sources"][0]["verticalUnits"]["fileUnit"], "ft");
  EXPECT_EQ(j["sources"][0]["verticalUnits"]["metersPerUnit"], kFootMeters);

  // An override says what it stood in for.
  Encoding unitless;
  unitless.metersPerUnit = kUsSurveyFootMeters;
  const fs::path bare = workDir() / "info-unitless.tif";
  writeRaster(bare, zion(), unitless);
  const fs::path overridden =
      tileOk(workDir(), "info-override", {bare.string()}, {"--z-units", "us-ft"});
  const ProgramRun overrideText = runUnitsProgram(GLOBE_EXE, {"info", overridden.string()});
  EXPECT_NE(overrideText.output.find("heights --z-units us-ft (file unit none) -> x0.3048006096 m"),
            std::string::npos)
      << overrideText.output;
}

TEST(TilerUnits, RastersWithoutA2x2CellOfValidSamplesAreRefused) {
  const double nan = std::nan("");
  const std::vector<std::pair<std::string, UnitsRaster>> refused = {
      {"one-by-one", smallRaster(1, 1, {1500})},
      {"two-by-one", smallRaster(2, 1, {1500, 1600})},
      {"one-by-two", smallRaster(1, 2, {1500, 1600})},
      {"one-valid", smallRaster(3, 3, {nan, nan, nan, nan, 1500, nan, nan, nan, nan})},
      {"one-row", smallRaster(3, 3, {1500, 1600, 1700, nan, nan, nan, nan, nan, nan})},
      {"one-column", smallRaster(3, 3, {nan, 1500, nan, nan, 1600, nan, nan, 1700, nan})},
      {"three-of-four", smallRaster(2, 2, {1500, 1600, 1700, nan})},
  };
  for (const auto& [name, raster] : refused) {
    SCOPED_TRACE(name);
    const fs::path tif = workDir() / (name + ".tif");
    writeRaster(tif, raster, Encoding{});
    const ProgramRun run = runGlobeTiler(workDir() / name, {tif.string()});
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find(tif.string() + ": fewer than 2x2 valid samples"), std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("nothing to tile"), std::string::npos) << run.output;
  }
  // One 2x2 cell of valid samples is enough, also inside no data.
  for (const auto& [name, raster] :
       {std::pair{std::string("two-by-two"), smallRaster(2, 2, {1500, 1600, 1700, 1800})},
        {"cell-in-no-data", smallRaster(4, 4,
                                        {nan, nan, nan, nan,    //
                                         nan, 1500, 1600, nan,  //
                                         nan, 1700, 1800, nan,  //
                                         nan, nan, nan, nan})}}) {
    SCOPED_TRACE(name);
    const fs::path tif = workDir() / (name + ".tif");
    writeRaster(tif, raster, Encoding{});
    tileOk(workDir(), name, {tif.string()});
  }
}

}  // namespace
}  // namespace globe::tiling
