// globe-bench-png-check: what checking a PNG before stb_image decodes it costs (formats/png_check:
// chunk lengths, and the image data inflated once by zlib to count its size against the header's),
// on 256x256 imagery tiles cut from the bundled Blue Marble (land, and sea), re-encoded as
// PNG. Three ways per tile: the check alone, stb_image's decode alone, and both (what
// decodeImageRgba does). Run with --benchmark_repetitions=5 and compare the medians of one run.
#include <benchmark/benchmark.h>
#include <stb_image.h>

#include <cstring>
#include <string>
#include <vector>

#include "formats/image_io.hpp"
#include "formats/png_check.hpp"
#include "tests/support/build_paths.hpp"

namespace {

using globe::formats::ImageRgba;

// A 256x256 crop of a bundled image at (x, y), as a PNG in memory.
std::vector<std::byte> pngTile(const std::string& file, int x, int y) {
  static std::vector<std::pair<std::string, ImageRgba>> loaded;
  const ImageRgba* image = nullptr;
  for (const auto& [name, i] : loaded) image = name == file ? &i : image;
  if (image == nullptr) {
    auto read = globe::formats::loadImageRgba(std::string(GLOBE_SOURCE_DIR) + "/data/imagery/" + file);
    if (!read) return {};
    loaded.emplace_back(file, std::move(*read));
    image = &loaded.back().second;
  }
  ImageRgba tile{256, 256, std::vector<uint8_t>(256 * 256 * 4)};
  for (int row = 0; row < 256; ++row) {
    const size_t from = (size_t(y + row) * size_t(image->widthPixels) + size_t(x)) * 4;
    std::memcpy(&tile.pixels[size_t(row) * 256 * 4], &image->pixels[from], 256 * 4);
  }
  auto png = globe::formats::encodePng(tile);
  return png ? *png : std::vector<std::byte>{};
}

const std::vector<std::byte>& tileFor(int which) {
  static const std::vector<std::byte> tiles[] = {
      pngTile("world.topo.bathy.200412.3x5400x2700.jpg", 4000, 900),  // Japan
      pngTile("world.topo.bathy.200412.3x5400x2700.jpg", 3000, 1700)};  // the Indian Ocean
  return tiles[which];
}

void decodeWithStb(const std::vector<std::byte>& png, benchmark::State& state) {
  int w = 0, h = 0, n = 0;
  unsigned char* pixels = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()),
                                                static_cast<int>(png.size()), &w, &h, &n, 4);
  if (pixels == nullptr) state.SkipWithError("stb_image could not decode the tile");
  benchmark::DoNotOptimize(pixels);
  stbi_image_free(pixels);
}

void BM_Check(benchmark::State& state) {
  const auto& png = tileFor(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    if (!globe::formats::checkPngStructure(png, "tile")) state.SkipWithError("refused");
  }
  state.SetLabel(std::to_string(png.size()) + " bytes");
}

void BM_Decode(benchmark::State& state) {
  const auto& png = tileFor(static_cast<int>(state.range(0)));
  for (auto _ : state) decodeWithStb(png, state);
}

void BM_CheckAndDecode(benchmark::State& state) {
  const auto& png = tileFor(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    if (!globe::formats::checkPngStructure(png, "tile")) state.SkipWithError("refused");
    decodeWithStb(png, state);
  }
}

BENCHMARK(BM_Check)->ArgName("tile")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Decode)->ArgName("tile")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckAndDecode)->ArgName("tile")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
BENCHMARK_MAIN();
