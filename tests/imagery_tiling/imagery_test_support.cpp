#include "tests/imagery_tiling/imagery_test_support.hpp"

#include <gtest/gtest.h>

#include "tests/support/tiler_test_fixture.hpp"

namespace globe::testing {

namespace fs = std::filesystem;

Result<imagery_tiling::ImageryTilerReport> tileLayer(const std::vector<std::string>& inputs,
                                                     const fs::path& out,
                                                     imagery_tiling::ImageryTilerOptions options) {
  options.inputs = inputs;
  options.outputDir = out;
  if (options.threads == 0) options.threads = 2;
  return imagery_tiling::runImageryTiler(options);
}

fs::path layerOf(const std::vector<std::string>& inputs, const std::string& name,
                 imagery_tiling::ImageryTilerOptions options) {
  const fs::path out = freshTempDir("imagery-" + name) / "layer";
  auto report = tileLayer(inputs, out, options);
  EXPECT_TRUE(report) << report.error();
  return out;
}

std::unique_ptr<streaming::ImageryStore> openStore(const fs::path& dir) {
  auto store = streaming::ImageryStore::open(dir);
  EXPECT_TRUE(store) << store.error();
  return store ? std::move(*store) : nullptr;
}

std::map<geo::TileId, formats::ImageRgba> tilesOf(streaming::ImageryStore& store, uint32_t level) {
  std::map<geo::TileId, formats::ImageRgba> tiles;
  const uint32_t p = store.manifest().packTilesPerSide;
  for (const formats::PackId& pack : store.manifest().levels.at(level).packs) {
    for (size_t slot = 0; slot < size_t{p} * p; ++slot) {
      const geo::TileId tile = formats::tileOfSlot(pack, slot, p);
      auto bytes = store.loadEncoded(tile);
      EXPECT_TRUE(bytes) << bytes.error();
      if (!bytes || !*bytes) continue;
      auto image = formats::decodeImageRgba(**bytes, "tile");
      EXPECT_TRUE(image) << image.error();
      if (image) tiles.emplace(tile, std::move(*image));
    }
  }
  return tiles;
}

}  // namespace globe::testing
