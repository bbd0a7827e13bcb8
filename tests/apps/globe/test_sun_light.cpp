// The terrain under the real Sun (--time) through the real program, over Fuji's cone in the
// bundled pyramid: noon brighter than midnight, the morning Sun on the east slopes and the
// evening Sun on the west ones; `globe sun` prints what the light is; bad times are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <string>

#include "formats/image_io.hpp"
#include "tests/apps/globe/run_globe.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;
using test::runGlobe;

// Straight down on Fuji's summit from 30 km, north up: the cone's east flank is the right half.
const std::string kOverFuji = " --camera 138.7274,35.3606,30000,0,-90,0 --size 160x160 ";

struct Halves {
  double west = 0, east = 0;
  double mean() const { return (west + east) / 2; }
};

// Mean luminance (0..255) of the left and right halves of the central disc (the cone).
Halves snapshotHalves(const std::string& time, const fs::path& dir,
                      const std::string& extra = "") {
  const fs::path out =
      dir / ("fuji-" + std::to_string(std::hash<std::string>{}(time + extra)) + ".png");
  const auto run = runGlobe("snapshot " + globe::testing::bundledPyramid().string() + kOverFuji +
                            "--no-sky --time " + time + " " + extra + " -o " + out.string());
  EXPECT_EQ(run.exitCode, 0) << run.output;
  auto image = formats::loadImageRgba(out);
  EXPECT_TRUE(image) << (image ? "" : image.error());
  Halves h;
  if (!image) return h;
  double sums[2] = {0, 0};
  int counts[2] = {0, 0};
  const int w = image->widthPixels, hgt = image->heightPixels;
  for (int y = 0; y < hgt; ++y) {
    for (int x = 0; x < w; ++x) {
      const int dx = x - w / 2, dy = y - hgt / 2;
      if (dx * dx + dy * dy > (w / 3) * (w / 3) || dx == 0) continue;
      const size_t i = 4 * (static_cast<size_t>(y) * w + static_cast<size_t>(x));
      const double luminance = 0.2126 * image->pixels[i] + 0.7152 * image->pixels[i + 1] +
                               0.0722 * image->pixels[i + 2];
      sums[dx > 0] += luminance;
      ++counts[dx > 0];
    }
  }
  h.west = sums[0] / counts[0];
  h.east = sums[1] / counts[1];
  return h;
}

TEST(SunLight, NightIsDarkAndMorningAndEveningLightOppositeSlopes) {
  const fs::path dir = globe::testing::freshTempDir("sun-light");
  // Japan is UTC+9: 06:00 (the Sun 16° up in the east-north-east), 12:00, 18:00 (11° up in the
  // west-north-west) and midnight on the June solstice.
  const Halves morning = snapshotHalves("2024-06-21T06:00+09:00", dir);
  const Halves noon = snapshotHalves("2024-06-21T12:00+09:00", dir);
  const Halves evening = snapshotHalves("2024-06-21T18:00+09:00", dir);
  const Halves night = snapshotHalves("2024-06-21T00:00+09:00", dir);
  std::printf("Fuji west/east luminance: morning %.1f/%.1f noon %.1f/%.1f evening %.1f/%.1f "
              "night %.1f/%.1f\n",
              morning.west, morning.east, noon.west, noon.east, evening.west, evening.east,
              night.west, night.east);
  EXPECT_GT(morning.east, 1.3 * morning.west) << "the morning Sun lights the east slopes";
  EXPECT_GT(evening.west, 1.3 * evening.east) << "the evening Sun lights the west slopes";
  EXPECT_LT(night.mean(), 0.15 * noon.mean()) << "the night side is dark";
  EXPECT_GT(night.mean(), 0.0) << "but not nothing: the night's floor";
}

// A night-lights layer (--night-layer; here the Blue Marble stands in for a city-lights image)
// shows only where the Sun has set: the same picture at noon, much brighter at midnight.
TEST(SunLight, NightLightsShineOnlyWhereTheSunHasSet) {
  const fs::path dir = globe::testing::freshTempDir("sun-night-lights");
  const std::string lights = "--night-layer " + globe::testing::blueMarbleLayer().string();
  const Halves noon = snapshotHalves("2024-06-21T12:00+09:00", dir);
  const Halves noonLit = snapshotHalves("2024-06-21T12:00+09:00", dir, lights);
  const Halves night = snapshotHalves("2024-06-21T00:00+09:00", dir);
  const Halves nightLit = snapshotHalves("2024-06-21T00:00+09:00", dir, lights);
  EXPECT_NEAR(noonLit.mean(), noon.mean(), 0.5) << "night lights by day";
  EXPECT_GT(nightLit.mean(), night.mean() + 20.0) << "the lights at night";
}

// Mean blue over red of rows [fromRow, toRow) of a snapshot (ground only: the view looks down).
double blueOverRed(const formats::ImageRgba& image, int fromRow, int toRow) {
  double blue = 0, red = 0;
  for (int y = fromRow; y < toRow; ++y) {
    for (int x = 0; x < image.widthPixels; ++x) {
      const size_t i = 4 * (static_cast<size_t>(y) * image.widthPixels + static_cast<size_t>(x));
      red += image.pixels[i];
      blue += image.pixels[i + 2];
    }
  }
  return blue / std::max(red, 1.0);
}

// Aerial perspective under the physical sky: ridges 20..40 km away, seen from 1,500 m at noon,
// take the air's blue (it lets less blue through than red and scatters the sky's colour in),
// the ground at the camera's feet hardly; the same view with --no-sky has no air.
TEST(SunLight, DistantRidgesTurnBlueThroughTheAir) {
  const fs::path dir = globe::testing::freshTempDir("sun-aerial");
  const std::string view = " --camera 138.45,35.45,1500,120,-12,0 --size 200x120 --no-shadows "
                           "--time 2024-06-21T12:00+09:00 ";
  std::map<std::string, formats::ImageRgba> shots;
  for (const std::string sky : {"", "--no-sky"}) {
    const fs::path out = dir / ("aerial" + sky + ".png");
    const auto run = runGlobe("snapshot " + globe::testing::bundledPyramid().string() + view +
                              sky + " -o " + out.string());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto image = formats::loadImageRgba(out);
    ASSERT_TRUE(image) << image.error();
    shots[sky] = std::move(*image);
  }
  // Rows 40..50 lie on ridges tens of km away (the horizon is near row 34), 110..120 at ~7 km.
  const double far = blueOverRed(shots[""], 40, 50) / blueOverRed(shots["--no-sky"], 40, 50);
  const double near = blueOverRed(shots[""], 110, 120) / blueOverRed(shots["--no-sky"], 110, 120);
  std::printf("blue/red with the air over without: far %.3f, near %.3f\n", far, near);
  EXPECT_GT(far, 1.15) << "distant ridges take the air's blue";
  EXPECT_LT(near, far) << "nearer ground less";
}

// Mean luminance (0..255) of a 200×200 view straight down on Zion Canyon from 12 km.
double zionLuminance(const std::string& time, const std::string& extra, const fs::path& dir) {
  const fs::path out =
      dir / ("zion-" + std::to_string(std::hash<std::string>{}(time + extra)) + ".png");
  const auto run = runGlobe("snapshot " + globe::testing::zionPyramid().string() +
                            " --camera -112.95,37.25,12000,0,-90,0 --size 200x200 --no-sky --time " +
                            time + " " + extra + " -o " + out.string());
  EXPECT_EQ(run.exitCode, 0) << run.output;
  auto image = formats::loadImageRgba(out);
  EXPECT_TRUE(image) << (image ? "" : image.error());
  if (!image) return 0.0;
  double sum = 0.0;
  for (size_t i = 0; i + 3 < image->pixels.size(); i += 4) {
    sum += 0.2126 * image->pixels[i] + 0.7152 * image->pixels[i + 1] +
           0.0722 * image->pixels[i + 2];
  }
  return sum / static_cast<double>(image->pixels.size() / 4);
}

// Shadows (collision/sun_visibility.hpp): the evening Sun (15° up in the west-north-west) leaves
// Zion's canyon floors and east-facing ledges under its west walls in shadow, darker than the
// same view without them; the Sun 70° up at noon casts almost none.
TEST(SunLight, ShadowsDarkenTheCanyonAtALowSunAndHardlyAtNoon) {
  const fs::path dir = globe::testing::freshTempDir("sun-shadows");
  const double low = zionLuminance("2024-06-21T19:30-06:00", "", dir);
  const double lowFlat = zionLuminance("2024-06-21T19:30-06:00", "--no-shadows", dir);
  const double noon = zionLuminance("2024-06-21T12:30-06:00", "", dir);
  const double noonFlat = zionLuminance("2024-06-21T12:30-06:00", "--no-shadows", dir);
  std::printf("Zion mean luminance, shadows/none: 19:30 %.1f/%.1f, 12:30 %.1f/%.1f\n", low,
              lowFlat, noon, noonFlat);
  EXPECT_LT(low, 0.95 * lowFlat) << "the low Sun's shadows";
  EXPECT_GT(noon, 0.99 * noonFlat) << "hardly a shadow at noon";
  EXPECT_LE(noon, noonFlat) << "a shadow never brightens";
}

// A path's keyframe "time"s move the Sun through the flight: dawn over Fuji in 2 s of path.
TEST(SunLight, KeyframeTimesMoveTheSunThroughAPlay) {
  const fs::path dir = globe::testing::freshTempDir("sun-play");
  std::ofstream(dir / "dawn.json") << R"({"interpolation": "linear", "keyframes": [
    {"t": 0, "lon": 138.7274, "lat": 35.3606, "height": 30000, "time": "2024-06-21T03:00+09:00"},
    {"t": 2, "lon": 138.7274, "lat": 35.3606, "height": 30000, "time": "2024-06-21T07:00+09:00"}]})";
  const auto run = runGlobe("play " + globe::testing::bundledPyramid().string() + " " +
                            (dir / "dawn.json").string() + " --out " + (dir / "out").string() +
                            " --fps 1 --size 96x96 --no-sky");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto mean = [&](const char* frame) {
    auto image = formats::loadImageRgba(dir / "out" / "frames" / frame);
    EXPECT_TRUE(image) << frame;
    double sum = 0;
    for (size_t i = 0; image && i < image->pixels.size(); i += 4) sum += image->pixels[i + 1];
    return image ? sum / static_cast<double>(image->pixels.size() / 4) : 0.0;
  };
  const double night = mean("00000.png"), dawn = mean("00001.png"), morning = mean("00002.png");
  std::printf("green at 03:00, 05:00, 07:00 JST: %.1f %.1f %.1f\n", night, dawn, morning);
  EXPECT_LT(night, 0.15 * morning);
  EXPECT_GT(dawn, 2 * night) << "the Sun has risen by 05:00";
}

TEST(SunLight, GlobeSunPrintsThePositionAndRefusesMistakes) {
  // The SPA paper's example place and time (geometric elevation; its zenith 50.11162° is with
  // refraction at 820 mbar): azimuth 194.34°.
  const auto run =
      runGlobe("sun --time 2003-10-17T12:30:30-07:00 --at -105.1786,39.742476 --height 1830.14");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("azimuth_deg,elevation_deg\n194.34"), std::string::npos)
      << run.output;
  const auto refracted = runGlobe("sun --time 2003-10-17T19:30:30Z --at -105.1786,39.742476 "
                                  "--height 1830.14 --refraction");
  ASSERT_EQ(refracted.exitCode, 0) << refracted.output;
  for (const auto& [arguments, says] :
       std::vector<std::pair<std::string, std::string>>{
           {"sun --time 2024-06-21T06:30 --at 0,0", "add Z for UTC"},
           {"sun --time 2024-02-30T06:30Z --at 0,0", "no such date"},
           {"sun --time 2024-06-21T06:30Z --at 200,0", "--at longitude"},
           {"sun --time 2024-06-21T06:30Z --at 0", "LON,LAT"},
           {"snapshot " + globe::testing::bundledPyramid().string() +
                " --camera 0,0,1e6 --time noon -o /dev/null",
            "--time 'noon'"}}) {
    const auto bad = runGlobe(arguments);
    EXPECT_EQ(bad.exitCode, 2) << arguments << "\n" << bad.output;
    EXPECT_NE(bad.output.find(says), std::string::npos) << arguments << "\n" << bad.output;
  }
}

}  // namespace
}  // namespace globe::app

namespace globe::app {
namespace {

// Honest blanks: `snapshot --verbose` says what the terrain under the camera was made from, fine
// data over Fuji and only the 20' world grid over Paris.
TEST(SnapshotVerbose, SaysTheTerrainsSourceAndSpacingUnderTheCamera) {
  const fs::path dir = globe::testing::freshTempDir("snapshot-verbose");
  const std::string pyramid = globe::testing::bundledPyramid().string();
  const auto fuji = runGlobe("snapshot " + pyramid +
                             " --camera 138.73,35.36,9000 --size 64x64 --verbose -o " +
                             (dir / "fuji.png").string());
  ASSERT_EQ(fuji.exitCode, 0) << fuji.output;
  EXPECT_NE(fuji.output.find("terrain under the camera: E138N35_FUJI.DEM, 3\" (~93 m)"),
            std::string::npos)
      << fuji.output;
  const auto paris = runGlobe("snapshot " + pyramid +
                              " --camera 2.35,48.86,20000 --size 64x64 -v -o " +
                              (dir / "paris.png").string());
  ASSERT_EQ(paris.exitCode, 0) << paris.output;
  EXPECT_NE(paris.output.find("terrain under the camera: ETOPO20.DEM, 20' (~37 km)"),
            std::string::npos)
      << paris.output;
  const auto quiet = runGlobe("snapshot " + pyramid + " --camera 2.35,48.86,20000 --size 64x64 -o " +
                              (dir / "quiet.png").string());
  EXPECT_EQ(quiet.output.find("terrain under the camera"), std::string::npos) << quiet.output;
  // Each layer's exposure: the dark Blue Marble lifted, or left alone with --exposure off.
  const std::string layer = " --layer " + globe::testing::blueMarbleLayer().string();
  const auto lifted = runGlobe("snapshot " + pyramid + " --camera 2.35,48.86,20000 --size 64x64 -v" +
                               layer + " -o " + (dir / "lifted.png").string());
  ASSERT_EQ(lifted.exitCode, 0) << lifted.output;
  EXPECT_NE(lifted.output.find("(a dark photo lifted: --exposure)"), std::string::npos)
      << lifted.output;
  const auto plain = runGlobe("snapshot " + pyramid + " --camera 2.35,48.86,20000 --size 64x64 -v" +
                              layer + " --exposure off -o " + (dir / "plain.png").string());
  EXPECT_NE(plain.output.find("layer 1 exposure: 1.00\n"), std::string::npos) << plain.output;
  const auto wrong = runGlobe("snapshot " + pyramid + " --camera 2.35,48.86,20000 --size 64x64" +
                              layer + " --exposure 0.5 -o " + (dir / "wrong.png").string());
  EXPECT_EQ(wrong.exitCode, 2) << wrong.output;
  EXPECT_NE(wrong.output.find("--exposure must be auto, off or a number >= 1, not '0.5'"),
            std::string::npos)
      << wrong.output;
}

}  // namespace
}  // namespace globe::app
