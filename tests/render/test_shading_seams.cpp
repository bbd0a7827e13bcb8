// No lighting seams at tile edges: nadir views of rough real terrain (Mount Fuji's and Zion's
// SRTM, bundled) rendered by the real `globe snapshot` from 20, 50 and 120 km, with tiles of
// several levels on screen, score at most 2.0 on the seam score
// (tools/bench_render/seam_score.hpp). Before tiles carried their apron (one-sided normals on their
// edges) these views scored 3.1-4.8.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>
#include <string>

#include "formats/image_io.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "tools/bench_render/seam_score.hpp"

namespace globe {
namespace {

namespace fs = std::filesystem;

struct SeamView {
  const char* name;
  const char* camera;  // LON,LAT,HEIGHT: straight down, north up
  const char* size;    // the whole image inside the rough source's extent
  bool zionPyramid = false;
  int scoredRows = 0;  // score only the top rows (0: all): the bottom of fuji_120km is the coast
};

const SeamView kSeamViews[] = {
    {"fuji_20km", "138.73,35.36,20000", "640x480"},
    {"fuji_50km", "138.50,35.50,50000", "640x480"},
    {"fuji_120km", "138.38,35.55,120000", "320x480", false, 440},
    {"zion_20km", "-113.05,37.32,20000", "640x480", true},
};

void PrintTo(const SeamView& view, std::ostream* out) { *out << view.name; }

class ShadingSeams : public ::testing::TestWithParam<SeamView> {};

TEST_P(ShadingSeams, NadirViewScoresAtMostTwo) {
  const SeamView& view = GetParam();
  const fs::path outDir = fs::path(globe::build_paths::binaryDir()) / "tests/render/golden-output";
  fs::create_directories(outDir);
  const fs::path image = outDir / (std::string("seams_") + view.name + ".png");
  const fs::path& pyramid =
      view.zionPyramid ? globe::testing::zionPyramid() : globe::testing::bundledPyramid();
  const std::string command = std::string(GLOBE_EXE) + " snapshot " + pyramid.string() +
                              " --camera " + view.camera + " --size " + view.size + " -o " +
                              image.string() + " > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  auto rgba = formats::loadImageRgba(image);
  ASSERT_TRUE(rgba) << rgba.error();
  if (view.scoredRows > 0 && view.scoredRows < rgba->heightPixels) {
    rgba->heightPixels = view.scoredRows;
    rgba->pixels.resize(size_t{4} * rgba->widthPixels * view.scoredRows);
  }
  const bench::SeamScore s = bench::seamScore(*rgba);
  EXPECT_LE(s.score, 2.0) << view.name << ": column " << s.worstColumn << " scores " << s.columns
                          << ", row " << s.worstRow << " scores " << s.rows << " (" << image << ")";
  EXPECT_GT(s.score, 1.0) << "a real view has some variation between its columns";
}

INSTANTIATE_TEST_SUITE_P(Views, ShadingSeams, ::testing::ValuesIn(kSeamViews),
                         [](const auto& param) { return std::string(param.param.name); });

// The score itself: a smooth relief-like image scores low, the same image with one faint
// straight step (6 of 255, as a tile edge's lighting step) high, at that column.
TEST(SeamScore, FindsAFaintStraightStep) {
  constexpr int kW = 200, kH = 150;
  formats::ImageRgba image{kW, kH, std::vector<uint8_t>(size_t{kW} * kH * 4, 255)};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(-2.0, 2.0);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const double value = 120 + 30 * std::sin(x / 7.0) * std::cos(y / 9.0) + noise(random);
      for (int c = 0; c < 3; ++c) {
        image.pixels[(static_cast<size_t>(y) * kW + x) * 4 + c] = static_cast<uint8_t>(value);
      }
    }
  }
  EXPECT_LT(bench::seamScore(image).score, 1.8);
  formats::ImageRgba stepped = image;
  for (int y = 0; y < kH; ++y) {
    for (int x = 120; x < kW; ++x) {
      for (int c = 0; c < 3; ++c) stepped.pixels[(static_cast<size_t>(y) * kW + x) * 4 + c] += 6;
    }
  }
  const bench::SeamScore s = bench::seamScore(stepped);
  EXPECT_GT(s.score, 2.0);  // fails the views' bound
  EXPECT_EQ(s.worstColumn, 119);
}

}  // namespace
}  // namespace globe
