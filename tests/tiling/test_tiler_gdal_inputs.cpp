// Any raster GDAL opens tiles to the same blocks as its GTOPO30 twin: the netCDF ETOPO20 (float,
// starting at 20°E, wrapping) and the Mount Fuji GeoTIFF (no data −32768) against the .DEM files.
#include <gtest/gtest.h>

#include <map>

#include "core/crc32.hpp"
#include "formats/pyramid_manifest.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "tiling/tiler.hpp"
#include "transport/atomic_file.hpp"

namespace globe::tiling {
namespace {

namespace fs = std::filesystem;

std::map<std::string, uint32_t> packChecksums(const fs::path& dir) {
  std::map<std::string, uint32_t> sums;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".pack") continue;
    auto bytes = transport::readWholeFile(entry.path(), 1ULL << 32);
    EXPECT_TRUE(bytes) << bytes.error();
    if (bytes) sums[fs::relative(entry.path(), dir).string()] = core::crc32(*bytes);
  }
  return sums;
}

fs::path tile(const std::vector<std::string>& inputs, const std::string& name) {
  TilerOptions options;
  options.inputs = inputs;
  options.outputDir = globe::testing::freshTempDir(name) / "pyramid";
  auto report = runTiler(options);
  EXPECT_TRUE(report) << report.error();
  return options.outputDir;
}

TEST(TilerGdalInputs, NetcdfAndGeotiffGiveTheSameBlocksAsGtopo30) {
  const fs::path original = fs::path(GLOBE_SOURCE_DIR) / "tests/data/dem/original";
  ASSERT_TRUE(fs::exists(original / "etopo20.cdf")) << original << " is missing";
  const std::string dem = std::string(GLOBE_SOURCE_DIR) + "/data/dem/";
  const auto native =
      packChecksums(tile({dem + "ETOPO20.DEM", dem + "E138N35_FUJI.DEM"}, "native"));
  const auto viaGdal = packChecksums(
      tile({(original / "etopo20.cdf").string(), (original / "mt_fuji_90m.tif").string()}, "gdal"));
  EXPECT_GT(native.size(), 20u);
  EXPECT_EQ(native, viaGdal);
}

}  // namespace
}  // namespace globe::tiling
