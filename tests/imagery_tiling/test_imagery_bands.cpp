// globe-tiler imagery picks the colour bands right (issue 28): by colour interpretation in any
// band order, by --bands, and with a warning when it has to guess; paletted, grey + alpha and
// 16-bit inputs drawn by their stated rules; --bounds refused for a georeferenced image. Every
// input is made here with GDAL from a crop of the bundled Landsat 8 scene over Zion.
#include <gdal.h>
#include <gdal_alg.h>
#include <gdal_utils.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "tests/imagery_tiling/imagery_test_support.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::imagery_tiling {
namespace {

namespace fs = std::filesystem;
using testing::layerOf;
using testing::openStore;
using testing::tileLayer;
using testing::tilesOf;

// GDALTranslate with command-line style arguments; the output path.
std::string translate(const std::string& source, const fs::path& output,
                      std::vector<std::string> arguments) {
  GDALAllRegister();
  std::vector<char*> argv;
  for (std::string& a : arguments) argv.push_back(a.data());
  argv.push_back(nullptr);
  GDALTranslateOptions* options = GDALTranslateOptionsNew(argv.data(), nullptr);
  GDALDatasetH in = GDALOpen(source.c_str(), GA_ReadOnly);
  EXPECT_NE(in, nullptr) << source;
  GDALDatasetH out = GDALTranslate(output.c_str(), in, options, nullptr);
  EXPECT_NE(out, nullptr) << output;
  GDALClose(out);
  GDALClose(in);
  GDALTranslateOptionsFree(options);
  return output.string();
}

// 160×160 pixels (4.8 km) of the Landsat 8 natural-colour scene over Zion: red rock, green
// valleys and grey-blue shadow, bands 1-3 interpreted as red, green, blue.
const fs::path& work() {
  static const fs::path dir = globe::testing::freshTempDir("imagery-bands");
  return dir;
}
const std::string& zionCrop() {
  static const std::string path =
      translate(std::string(GLOBE_SOURCE_DIR) + "/data/imagery/zion-landsat8-rgb.tif",
                work() / "rgb.tif", {"-srcwin", "400", "600", "160", "160"});
  return path;
}
// Landsat's own band order (blue, green, red, then near- and short-wave infrared: here three
// copies in their place), with no colour interpretation, as a band stack comes out of
// gdal_merge or a download.
const std::string& sixBandStack() {
  static const std::string path =
      translate(zionCrop(), work() / "stack6.tif",
                {"-b", "3", "-b", "2", "-b", "1", "-b", "1", "-b", "2", "-b", "3", "-colorinterp",
                 "undefined,undefined,undefined,undefined,undefined,undefined"});
  return path;
}

struct Layer {
  fs::path dir;
  std::vector<std::string> warnings;
  std::string bands, stretch;
  std::map<geo::TileId, formats::ImageRgba> finest;
};

Layer tile(const std::string& input, const std::string& name, ImageryTilerOptions options = {}) {
  Layer layer;
  layer.dir = globe::testing::freshTempDir("imagery-bands-" + name) / "layer";
  auto report = tileLayer({input}, layer.dir, options);
  EXPECT_TRUE(report) << report.error();
  if (!report) return layer;
  layer.warnings = report->warnings;
  auto store = openStore(layer.dir);
  if (!store) return layer;
  layer.bands = store->manifest().sources.at(0).bands;
  layer.stretch = store->manifest().sources.at(0).stretch;
  layer.finest = tilesOf(*store, store->manifest().maxLevel());
  return layer;
}

const Layer& original() {
  static const Layer layer = tile(zionCrop(), "rgb");
  return layer;
}

// Mean |a − b| over the colour channels of pixels opaque in both, with a's channels taken in
// `order` (2,1,0 compares a's blue with b's red...); pixels compared in *count.
double meanDifference(const Layer& a, const Layer& b, std::array<int, 3> order, size_t* count) {
  double sum = 0;
  *count = 0;
  for (const auto& [id, image] : a.finest) {
    const auto other = b.finest.find(id);
    if (other == b.finest.end()) continue;
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
      if (image.pixels[i + 3] != 255 || other->second.pixels[i + 3] != 255) continue;
      for (size_t c = 0; c < 3; ++c) {
        sum += std::abs(int(image.pixels[i + size_t(order[c])]) - int(other->second.pixels[i + c]));
      }
      ++*count;
    }
  }
  return *count > 0 ? sum / (3.0 * double(*count)) : 1e9;
}

void expectSamePixels(const Layer& a, const Layer& b) {
  ASSERT_FALSE(a.finest.empty());
  ASSERT_EQ(a.finest.size(), b.finest.size());
  for (const auto& [id, image] : a.finest) {
    ASSERT_TRUE(b.finest.count(id)) << id.level << "/" << id.x << "/" << id.y;
    EXPECT_TRUE(image.pixels == b.finest.at(id).pixels) << id.level << "/" << id.x << "/" << id.y;
  }
}

TEST(ImageryBands, TheOriginalIsOpaqueRgb) {
  EXPECT_EQ(original().bands, "RGB");
  EXPECT_TRUE(original().warnings.empty());
  EXPECT_GE(original().finest.size(), 2u);
}

TEST(ImageryBands, SixBandsWithoutInterpretationDrawOneTwoThreeWithAWarning) {
  const Layer six = tile(sixBandStack(), "six");
  ASSERT_EQ(six.warnings.size(), 1u);
  EXPECT_EQ(six.warnings[0], sixBandStack() +
                                 ": 6 bands without red/green/blue interpretation; drawing bands "
                                 "1,2,3 as red,green,blue (choose with --bands R,G,B)");
  EXPECT_EQ(six.bands, "bands 1,2,3 as RGB (other bands unused, none is alpha)");
  // Bands 1,2,3 are blue, green, red: the picture comes out with red and blue swapped.
  size_t compared = 0;
  EXPECT_LT(meanDifference(six, original(), {2, 1, 0}, &compared), 1.5);
  EXPECT_GT(compared, 50'000u);
  EXPECT_GT(meanDifference(six, original(), {0, 1, 2}, &compared), 10.0);
}

TEST(ImageryBands, ChosenBandsDrawTheRightColours) {
  ImageryTilerOptions options;
  options.input.bands = {3, 2, 1};
  const Layer chosen = tile(sixBandStack(), "six-321", options);
  EXPECT_TRUE(chosen.warnings.empty());
  EXPECT_EQ(chosen.bands, "bands 3,2,1 as RGB (--bands) (other bands unused, none is alpha)");
  expectSamePixels(chosen, original());
}

TEST(ImageryBands, BandNumbersBeyondTheFileAreRefused) {
  ImageryTilerOptions options;
  options.input.bands = {7, 2, 1};
  const fs::path out = globe::testing::freshTempDir("imagery-bands-range") / "layer";
  auto refused = tileLayer({sixBandStack()}, out, options);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error(), sixBandStack() + ": --bands 7,2,1 names band 7, but it has 6 bands");
  EXPECT_FALSE(fs::exists(out / "layer.json"));
}

TEST(ImageryBands, BgrOrderWithInterpretationDrawsLikeTheOriginal) {
  const std::string bgr =
      translate(zionCrop(), work() / "bgr.tif",
                {"-b", "3", "-b", "2", "-b", "1", "-colorinterp", "blue,green,red"});
  const Layer layer = tile(bgr, "bgr");
  EXPECT_TRUE(layer.warnings.empty());
  EXPECT_EQ(layer.bands, "RGB (bands 3,2,1)");
  expectSamePixels(layer, original());
}

TEST(ImageryBands, GreyWithAlpha) {
  // Band 1: the scene's green; band 2: alpha, 0 over the northern half of the crop.
  const std::string grey = translate(zionCrop(), work() / "grey_alpha.tif",
                                     {"-b", "2", "-b", "2", "-colorinterp", "gray,alpha"});
  GDALDatasetH ds = GDALOpen(grey.c_str(), GA_Update);
  ASSERT_NE(ds, nullptr);
  std::vector<uint8_t> alpha(160 * 160);
  for (size_t i = 0; i < alpha.size(); ++i) alpha[i] = i / 160 < 80 ? 0 : 255;
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 2), GF_Write, 0, 0, 160, 160, alpha.data(), 160, 160,
                         GDT_Byte, 0, 0),
            CE_None);
  GDALClose(ds);
  const Layer layer = tile(grey, "grey-alpha");
  EXPECT_TRUE(layer.warnings.empty());
  EXPECT_EQ(layer.bands, "grey + alpha (band 2)");
  size_t opaque = 0, transparent = 0, notGrey = 0;
  for (const auto& [id, image] : layer.finest) {
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
      opaque += image.pixels[i + 3] == 255;
      transparent += image.pixels[i + 3] == 0;
      notGrey += image.pixels[i + 3] != 0 &&
                 (image.pixels[i] != image.pixels[i + 1] || image.pixels[i] != image.pixels[i + 2]);
    }
  }
  EXPECT_EQ(notGrey, 0u);  // PNG tiles (they hold transparency): lossless
  // The crop's southern half opaque, its northern half and the tiles beyond it transparent.
  EXPECT_GT(opaque, 20'000u);
  EXPECT_GT(transparent, 20'000u);
  // Where opaque, grey is the original's green (within JPEG's loss in the original).
  double sum = 0;
  size_t compared = 0;
  for (const auto& [id, image] : layer.finest) {
    ASSERT_TRUE(original().finest.count(id));
    const auto& reference = original().finest.at(id).pixels;
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
      if (image.pixels[i + 3] != 255 || reference[i + 3] != 255) continue;
      sum += std::abs(int(image.pixels[i]) - int(reference[i + 1]));
      ++compared;
    }
  }
  ASSERT_GT(compared, 20'000u);
  EXPECT_LT(sum / double(compared), 2.0);
}

TEST(ImageryBands, PaletteOfTheSceneIsExpanded) {
  // The scene reduced to 256 colours (median cut, dithered), against the same palette expanded
  // to RGB by GDAL: the same pixels.
  GDALDatasetH rgb = GDALOpen(zionCrop().c_str(), GA_ReadOnly);
  ASSERT_NE(rgb, nullptr);
  GDALRasterBandH r = GDALGetRasterBand(rgb, 1), g = GDALGetRasterBand(rgb, 2),
                  b = GDALGetRasterBand(rgb, 3);
  GDALColorTableH table = GDALCreateColorTable(GPI_RGB);
  ASSERT_EQ(GDALComputeMedianCutPCT(r, g, b, nullptr, 256, table, nullptr, nullptr), CE_None);
  const std::string paletted = (work() / "palette.tif").string();
  GDALDatasetH out =
      GDALCreate(GDALGetDriverByName("GTiff"), paletted.c_str(), 160, 160, 1, GDT_Byte, nullptr);
  double geo[6];
  GDALGetGeoTransform(rgb, geo);
  GDALSetGeoTransform(out, geo);
  GDALSetProjection(out, GDALGetProjectionRef(rgb));
  GDALRasterBandH indices = GDALGetRasterBand(out, 1);
  ASSERT_EQ(GDALDitherRGB2PCT(r, g, b, indices, table, nullptr, nullptr), CE_None);
  GDALSetRasterColorTable(indices, table);
  GDALSetRasterColorInterpretation(indices, GCI_PaletteIndex);
  GDALClose(out);
  GDALDestroyColorTable(table);
  GDALClose(rgb);
  const std::string expanded =
      translate(paletted, work() / "palette_expanded.tif", {"-expand", "rgb"});
  const Layer layer = tile(paletted, "palette");
  EXPECT_EQ(layer.bands, "palette");
  expectSamePixels(layer, tile(expanded, "palette-expanded"));
  size_t compared = 0;
  EXPECT_LT(meanDifference(layer, original(), {0, 1, 2}, &compared), 8.0);  // 256 colours
}

// The crop as UInt16: value × 100 + 1000 (as Landsat's digital numbers, but exactly invertible).
const std::string& sixteenBit() {
  static const std::string path = translate(
      zionCrop(), work() / "uint16.tif", {"-ot", "UInt16", "-scale", "0", "255", "1000", "26500"});
  return path;
}

// The value below which `fraction` of the band's samples lie (the smallest v with
// count(≤ v) ≥ fraction × n), from the samples themselves.
int samplePercentile(const std::string& path, int band, double fraction) {
  GDALDatasetH ds = GDALOpen(path.c_str(), GA_ReadOnly);
  std::vector<uint16_t> values(160 * 160);
  EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(ds, band), GF_Read, 0, 0, 160, 160, values.data(), 160,
                         160, GDT_UInt16, 0, 0),
            CE_None);
  GDALClose(ds);
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<size_t>(std::ceil(fraction * double(values.size())));
  return values[std::max<size_t>(rank, 1) - 1];
}

TEST(ImageryBands, SixteenBitByTheStatedRule) {
  // --scale MIN,MAX undoes the ×100 + 1000 exactly: the original's pixels.
  ImageryTilerOptions linear;
  linear.input.scale = ImageryStretch{1000, 26500};
  const Layer undone = tile(sixteenBit(), "uint16-linear", linear);
  EXPECT_EQ(undone.stretch, "linear 1000..26500 to 0..255");
  expectSamePixels(undone, original());

  // Default: each band's own 2nd and 98th percentiles.
  const Layer stretched = tile(sixteenBit(), "uint16-auto");
  std::string expected = "2-98% per band:";
  for (int b = 1; b <= 3; ++b) {
    expected += " " + std::to_string(samplePercentile(sixteenBit(), b, 0.02)) + ".." +
                std::to_string(samplePercentile(sixteenBit(), b, 0.98));
  }
  EXPECT_EQ(stretched.stretch, expected);
  // Nothing is written beside the input (GDAL's histogram would cache itself in an .aux.xml).
  EXPECT_FALSE(fs::exists(sixteenBit() + ".aux.xml"));
  // The stretch spreads each channel over most of 0..255, clipping about 2 % at each end.
  for (size_t c = 0; c < 3; ++c) {
    size_t dark = 0, bright = 0, all = 0;
    for (const auto& [id, image] : stretched.finest) {
      for (size_t i = 0; i < image.pixels.size(); i += 4) {
        if (image.pixels[i + 3] != 255) continue;
        dark += image.pixels[i + c] <= 3;
        bright += image.pixels[i + c] >= 252;
        ++all;
      }
    }
    EXPECT_GT(dark * 200, all) << c;  // > 0.5 %
    EXPECT_GT(bright * 200, all) << c;
    EXPECT_LT(dark * 100, all * 5) << c;  // < 5 %
    EXPECT_LT(bright * 100, all * 5) << c;
  }
}

// A DEM given to the imagery tiler is refused, naming the file, its sample type and the command
// that tiles elevation, when its band holds heights: signed samples (the bundled SRTM over Zion
// as Int16 and as Float32) or a unit of length (as UInt16 with "metre"); --force draws it as
// grey. One unsigned 16-bit band (the SRTM as bundled, like a Landsat band) is drawn with a
// warning naming the file; an 8-bit grey image is imagery, drawn without one.
TEST(ImageryBands, AnElevationModelIsRefusedUnlessForced) {
  const std::string srtm =
      translate(std::string(GLOBE_SOURCE_DIR) + "/data/dem/zion-srtm3.tif",
                work() / "srtm.tif", {"-srcwin", "100", "100", "120", "120"});
  const std::string int16 = translate(srtm, work() / "srtm-int16.tif", {"-ot", "Int16"});
  const std::string floats = translate(srtm, work() / "srtm-float.tif", {"-ot", "Float32"});
  const std::string metres = translate(srtm, work() / "srtm-metres.tif", {});
  GDALDatasetH withUnit = GDALOpen(metres.c_str(), GA_Update);
  ASSERT_NE(withUnit, nullptr);
  EXPECT_EQ(GDALSetRasterUnitType(GDALGetRasterBand(withUnit, 1), "metre"), CE_None);
  GDALClose(withUnit);
  for (const auto& [path, type] : {std::pair{int16, "Int16"}, std::pair{floats, "Float32"},
                                   std::pair{metres, "UInt16"}}) {
    const fs::path out = globe::testing::freshTempDir("imagery-bands-dem") / "layer";
    auto refused = tileLayer({path}, out, {});
    ASSERT_FALSE(refused) << path;
    EXPECT_NE(refused.error().find(path + ": one band of " + type + " samples"),
              std::string::npos) << refused.error();
    EXPECT_NE(refused.error().find("globe-tiler -o PYRAMID " + path), std::string::npos);
    EXPECT_NE(refused.error().find("--force"), std::string::npos);
    EXPECT_FALSE(fs::exists(out / "layer.json"));
  }
  ImageryTilerOptions forced;
  forced.input.allowElevation = true;
  EXPECT_EQ(tile(int16, "srtm-forced", forced).bands, "grey, nodata transparent");
  const Layer unsignedBand = tile(srtm, "srtm-uint16");
  ASSERT_EQ(unsignedBand.warnings.size(), 1u);
  EXPECT_NE(unsignedBand.warnings[0].find(srtm + ": one band of UInt16 samples"),
            std::string::npos) << unsignedBand.warnings[0];
  EXPECT_NE(unsignedBand.warnings[0].find("elevation model"), std::string::npos);
  const std::string grey = translate(zionCrop(), work() / "grey8.tif", {"-b", "1"});
  const Layer greyLayer = tile(grey, "grey-8bit");
  EXPECT_EQ(greyLayer.bands, "grey");
  EXPECT_TRUE(greyLayer.warnings.empty());
}

TEST(ImageryBands, BoundsForAGeoreferencedImageIsAnError) {
  ImageryTilerOptions options;
  options.input.bounds = formats::BoundsDegrees{-180, -90, 180, 90};
  const fs::path out = globe::testing::freshTempDir("imagery-bands-bounds") / "layer";
  auto refused = tileLayer({zionCrop()}, out, options);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error(), zionCrop() +
                                 " is georeferenced; --bounds is only for images without "
                                 "georeferencing");
  EXPECT_FALSE(fs::exists(out / "layer.json"));
}

// The command line: the warning printed, the rules in --help, bad --bands refused.
std::string runTiler(const std::string& arguments, int* status) {
  const std::string command = std::string(GLOBE_TILER_EXE) + " imagery " + arguments + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  std::string output;
  char buffer[4096];
  while (pipe != nullptr && std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  *status = pipe != nullptr ? ::pclose(pipe) : -1;
  return output;
}

TEST(ImageryBands, CommandLinePrintsTheWarningAndStatesTheRules) {
  int status = 0;
  const fs::path out = globe::testing::freshTempDir("imagery-bands-cli") / "layer";
  std::string output = runTiler("-q -j2 -o " + out.string() + " " + sixBandStack(), &status);
  EXPECT_EQ(status, 0) << output;
  EXPECT_NE(output.find("globe-tiler imagery: warning: " + sixBandStack() +
                        ": 6 bands without red/green/blue interpretation"),
            std::string::npos)
      << output;
  output = runTiler("--bands 3,2 -o " + out.string() + "-x " + sixBandStack(), &status);
  EXPECT_NE(status, 0);
  EXPECT_NE(output.find("--bands must be R,G,B or R,G,B,A"), std::string::npos) << output;
  output = runTiler("--help", &status);
  EXPECT_EQ(status, 0);
  for (const char* rule : {"--bands R,G,B[,A]", "colour interpretation", "BGR", "warning",
                           "2nd to its 98th percentile", "--scale MIN,MAX",
                           "an error when every input is georeferenced"}) {
    EXPECT_NE(output.find(rule), std::string::npos) << rule << "\n" << output;
  }
}

}  // namespace
}  // namespace globe::imagery_tiling
