// AVIF imagery from a service: the 50 real USGS topo tiles over Mt Whitney (512 px WebP, zoom
// 8-15) rewritten as lossless AVIF into a PMTiles archive read as the same tiles as the real WebP
// archive they came from.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "formats/image_io.hpp"
#include "formats/pmtiles.hpp"
#include "publish/pmtiles_writer.hpp"
#include "services/imagery_services.hpp"
#include "tests/services/whitney_tiles.hpp"
#include "tests/support/avif_encoder.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::services {
namespace {

namespace fs = std::filesystem;

const std::string kTree = std::string(GLOBE_SOURCE_DIR) +
                          "/tests/data/interop/raster-tiles/xyz-usgs-topo-mt-whitney-webp512";

std::vector<std::byte> readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  const auto* p = reinterpret_cast<const std::byte*>(text.data());
  return {p, p + text.size()};
}

struct SourceTile {
  uint64_t id;
  uint32_t z, x, y;
  fs::path file;
};

// The tree's tiles in PMTiles order.
std::vector<SourceTile> treeTiles() {
  std::vector<SourceTile> tiles;
  for (const auto& entry : fs::recursive_directory_iterator(kTree)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".webp") continue;
    const fs::path& p = entry.path();
    const auto z = static_cast<uint32_t>(std::stoul(p.parent_path().parent_path().filename()));
    const auto x = static_cast<uint32_t>(std::stoul(p.parent_path().filename()));
    const auto y = static_cast<uint32_t>(std::stoul(p.stem()));
    tiles.push_back({formats::pmtilesTileId(z, x, y), z, x, y, p});
  }
  std::sort(tiles.begin(), tiles.end(),
            [](const SourceTile& a, const SourceTile& b) { return a.id < b.id; });
  return tiles;
}

fs::path avifArchive(const fs::path& dir) {
  const fs::path archive = dir / "whitney-avif.pmtiles";
  auto writer = publish::PmtilesWriter::create(archive);
  EXPECT_TRUE(writer) << writer.error();
  if (!writer) return {};
  uint32_t minZoom = 99, maxZoom = 0;
  for (const SourceTile& tile : treeTiles()) {
    auto image = formats::decodeImageRgba(readBytes(tile.file), tile.file.string());
    EXPECT_TRUE(image) << image.error();
    if (!image) return {};
    const std::vector<std::byte> avif = globe::testing::encodeAvifLossless(*image);
    EXPECT_FALSE(avif.empty()) << tile.file;
    EXPECT_TRUE((*writer)->add(tile.z, tile.x, tile.y, avif)) << tile.file;
    minZoom = std::min(minZoom, tile.z);
    maxZoom = std::max(maxZoom, tile.z);
  }
  // The real archive's header (its bounds, zooms and centre), for tiles of another type.
  const fs::path real = std::string(GLOBE_SOURCE_DIR) +
                        "/tests/data/interop/pmtiles/usgs-mt-whitney-8-15-webp-512.pmtiles";
  const std::vector<std::byte> realBytes = readBytes(real);
  auto header = formats::decodePmtilesHeader(realBytes, realBytes.size(), real.string());
  EXPECT_TRUE(header) << header.error();
  if (!header) return {};
  EXPECT_EQ(header->minZoom, minZoom);
  EXPECT_EQ(header->maxZoom, maxZoom);
  header->tileType = formats::PmtilesTileType::Avif;
  auto summary = (*writer)->finish(*header, R"({"tileSize": 512})");  // as the real one says
  EXPECT_TRUE(summary) << summary.error();
  return archive;
}

TEST(AvifTiles, APmtilesArchiveOfAvifTilesReadsAsTheWebpArchive) {
  const fs::path dir = globe::testing::freshTempDir("avif-tiles");
  const fs::path archive = avifArchive(dir);
  ASSERT_FALSE(archive.empty());
  transport::NetworkSettings settings;
  settings.useCache = false;
  const auto network = std::make_shared<transport::Network>(settings);
  auto avif = openImageryTiles("pmtiles:" + archive.string(), network);
  ASSERT_TRUE(avif) << avif.error();
  auto webp =
      openImageryTiles("pmtiles:" + std::string(GLOBE_SOURCE_DIR) +
                           "/tests/data/interop/pmtiles/usgs-mt-whitney-8-15-webp-512.pmtiles",
                       network);
  ASSERT_TRUE(webp) << webp.error();
  const size_t compared = testing::compareTilesAtWhitney(**avif, **webp);
  EXPECT_GE(compared, 6u);
}

}  // namespace
}  // namespace globe::services
