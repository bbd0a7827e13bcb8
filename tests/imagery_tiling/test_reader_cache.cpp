// The imagery tiler keeps a bounded number of readers open per worker (least recently used closed
// first), so a layer of hundreds of inputs tiles under a small file-descriptor limit, identical to
// a run without the limit. Real imagery: Blue Marble cut into 512 georeferenced GeoTIFF pieces,
// with a NAIP crop in UTM (a warped reader) among them.
#include <gdal.h>
#include <gdal_utils.h>
#include <gtest/gtest.h>

#include <cpl_string.h>

#include <string>
#include <vector>

#include "imagery_tiling/imagery_input.hpp"
#include "imagery_tiling/reader_cache.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/command_run.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::imagery_tiling::reader_cache_test {
namespace {

namespace fs = std::filesystem;

const std::string kTiler = GLOBE_TILER_EXE;

std::string imagery(const std::string& name) {
  return std::string(GLOBE_SOURCE_DIR) + "/tests/data/imagery/" + name;
}

// The 512 x 256 Blue Marble (a plate carree world) as 32 x 16 GeoTIFFs of 16 x 16 pixels, written
// once; then the NAIP crop.
const std::vector<std::string>& pieces() {
  static const std::vector<std::string> all = [] {
    std::vector<std::string> paths;
    GDALAllRegister();
    const fs::path dir = globe::testing::freshTempDir("imagery-pieces");
    GDALDatasetH world = GDALOpen(imagery("bmng_world_512x256.jpg").c_str(), GA_ReadOnly);
    EXPECT_NE(world, nullptr);
    if (world == nullptr) return paths;
    constexpr int kSide = 16;
    constexpr double kDegreesPerPixel = 360.0 / 512;
    for (int row = 0; row < 256 / kSide; ++row) {
      for (int col = 0; col < 512 / kSide; ++col) {
        const double west = -180 + col * kSide * kDegreesPerPixel;
        const double north = 90 - row * kSide * kDegreesPerPixel;
        const std::vector<std::string> args = {"-q",
                                               "-of",
                                               "GTiff",
                                               "-srcwin",
                                               std::to_string(col * kSide),
                                               std::to_string(row * kSide),
                                               std::to_string(kSide),
                                               std::to_string(kSide),
                                               "-a_srs",
                                               "EPSG:4326",
                                               "-a_ullr",
                                               std::to_string(west),
                                               std::to_string(north),
                                               std::to_string(west + kSide * kDegreesPerPixel),
                                               std::to_string(north - kSide * kDegreesPerPixel)};
        char** argv = nullptr;
        for (const std::string& a : args) argv = CSLAddString(argv, a.c_str());
        GDALTranslateOptions* options = GDALTranslateOptionsNew(argv, nullptr);
        const std::string path =
            (dir / ("p" + std::to_string(row) + "_" + std::to_string(col) + ".tif")).string();
        GDALDatasetH piece = GDALTranslate(path.c_str(), world, options, nullptr);
        EXPECT_NE(piece, nullptr) << path;
        if (piece != nullptr) GDALClose(piece);
        GDALTranslateOptionsFree(options);
        CSLDestroy(argv);
        paths.push_back(path);
      }
    }
    GDALClose(world);
    paths.push_back(imagery("naip_rgbn_utm14_crop.tif"));
    return paths;
  }();
  return all;
}

TEST(ReaderCache, KeepsTheMostRecentlyUsedAndReopensTheRest) {
  auto inputs = describeImageryInputs({pieces()[0], pieces()[1], pieces()[2]}, {});
  ASSERT_TRUE(inputs) << inputs.error();
  ReaderCache cache(*inputs, 2);
  ASSERT_TRUE(cache.get(0));
  ASSERT_TRUE(cache.get(1));
  ASSERT_TRUE(cache.get(0));  // kept: 0 is now the most recently used
  EXPECT_EQ(cache.opened(), 2U);
  ASSERT_TRUE(cache.get(2));  // closes 1, the least recently used
  EXPECT_EQ(cache.openReaders(), 2U);
  ASSERT_TRUE(cache.get(0));
  EXPECT_EQ(cache.opened(), 3U);
  ASSERT_TRUE(cache.get(1));  // reopened
  EXPECT_EQ(cache.opened(), 4U);
  EXPECT_EQ(cache.openReaders(), 2U);
}

TEST(ReaderCache, ReadersPerWorkerShareHalfTheDescriptorLimit) {
  // The test's own limit: whatever it is, the workers' readers stay within half of it (but at
  // least 2 each, and no more than 256).
  const size_t one = readersPerWorker(1), four = readersPerWorker(4);
  EXPECT_GE(four, 2U);
  EXPECT_LE(one, 256U);
  EXPECT_LE(four, one);
}

TEST(ReaderCache, FiveHundredInputsTileUnderASixtyFourDescriptorLimit) {
  const std::vector<std::string>& inputs = pieces();
  ASSERT_EQ(inputs.size(), 513U);
  std::string list;
  for (const std::string& input : inputs) list += " " + input;
  const fs::path dir = globe::testing::freshTempDir("imagery-many-inputs");
  const std::string command = kTiler + " imagery -q -j 2 --pack-tiles 4 -o ";
  const auto free = globe::testing::runCommand(command + (dir / "free").string() + list);
  ASSERT_EQ(free.exitCode, 0) << free.output;
  const auto limited =
      globe::testing::runCommand("ulimit -n 64 && " + command + (dir / "limited").string() + list);
  ASSERT_EQ(limited.exitCode, 0) << limited.output;
  const auto tiles = globe::testing::checksums(dir / "free");
  EXPECT_GT(tiles.size(), 2U);
  EXPECT_EQ(tiles, globe::testing::checksums(dir / "limited"));
}

}  // namespace
}  // namespace globe::imagery_tiling::reader_cache_test
