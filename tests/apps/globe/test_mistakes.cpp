// A mistyped command line gets the word that was meant: the edit distance behind it, and the real
// program's messages for a misspelt subcommand and misspelt options.
#include <gtest/gtest.h>

#include <filesystem>

#include "apps/globe/did_you_mean.hpp"
#include "formats/image_io.hpp"
#include "tests/apps/globe/run_globe.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;
using test::runGlobe;

TEST(DidYouMean, EditDistanceCountsInsertionsDeletionsChangesAndSwaps) {
  EXPECT_EQ(editDistance("", ""), 0u);
  EXPECT_EQ(editDistance("camera", "camera"), 0u);
  EXPECT_EQ(editDistance("camra", "camera"), 1u);    // one letter left out
  EXPECT_EQ(editDistance("cammera", "camera"), 1u);  // one too many
  EXPECT_EQ(editDistance("camefa", "camera"), 1u);   // one changed
  EXPECT_EQ(editDistance("camrea", "camera"), 1u);   // two swapped
  EXPECT_EQ(editDistance("", "size"), 4u);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
}

TEST(DidYouMean, OnlyACloseAndUnambiguousWordIsSuggested) {
  const std::vector<std::string> options = {"--camera", "--size", "--sse", "--layer", "--lighting"};
  EXPECT_EQ(closestWord("--camra", options), "--camera");
  EXPECT_EQ(closestWord("--lyaer", options), "--layer");
  EXPECT_EQ(closestWord("--zzzzzzzz", options), std::nullopt) << "nothing near";
  EXPECT_EQ(closestWord("--ssize", options), "--size");
  EXPECT_EQ(closestWord("--sie", options), std::nullopt) << "--size and --sse are both one away";
  EXPECT_EQ(closestWord("--size", options), std::nullopt) << "an exact word needs no hint";
}

TEST(DidYouMean, TheProgramSuggestsTheSubcommandAndTheOptions) {
  auto run = runGlobe("snapshto pyramid");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("no subcommand \"snapshto\"; did you mean `globe snapshot`?"),
            std::string::npos) << run.output;
  run = runGlobe("snapshot pyramid --camra 138.7,35.3,9000 --siz=480x270 -o x.png");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("no option --camra; did you mean --camera?"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("no option --siz; did you mean --size?"), std::string::npos)
      << run.output;
  run = runGlobe("snapshot-worke");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_EQ(run.output.find("did you mean"), std::string::npos)
      << "the hidden worker is never suggested\n" << run.output;
}

// A file given to the wrong option says which option it belongs to, and the run stops.
TEST(Mistakes, AnOverlayGivenAsALayerAndALayerAsAnOverlayNameTheRightOption) {
  const std::string pyramid = globe::testing::bundledPyramid().string();
  const std::string kml = std::string(GLOBE_SOURCE_DIR) + "/data/overlays/fuji-demo.kml";
  auto run = runGlobe("snapshot " + pyramid + " --camera 138.7,35.3,9000 --layer " + kml +
                      " -o /nonexistent/x.png");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--layer " + kml + ": not a layer (" + kml +
                            " is an overlay file: give it with --overlay)"),
            std::string::npos) << run.output;
  const std::string layer = globe::testing::blueMarbleLayer().string();
  run = runGlobe("snapshot " + pyramid + " --camera 138.7,35.3,9000 --overlay " + layer +
                 " -o /nonexistent/x.png");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("(" + layer + " is a layer folder: give it with --layer)"),
            std::string::npos) << run.output;
}

// A camera given inside the terrain (100 m above the ellipsoid on Fuji's flank) is lifted out
// of it with a warning, and the picture shows ground, not the terrain's black inside.
TEST(Mistakes, ACameraInsideTheTerrainIsLiftedOutWithAWarning) {
  const fs::path dir = globe::testing::freshTempDir("inside-terrain");
  const auto run = runGlobe("snapshot " + globe::testing::bundledPyramid().string() +
                            " --camera 138.73,35.36,100,0,-20,0 --size 96x54 -o " +
                            (dir / "lifted.png").string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("the camera at 100.0 m is inside the terrain ("), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find(" m there): lifted to "), std::string::npos) << run.output;
  auto image = formats::loadImageRgba(dir / "lifted.png");
  ASSERT_TRUE(image) << image.error();
  size_t black = 0;
  for (size_t i = 0; i + 3 < image->pixels.size(); i += 4) {
    black += image->pixels[i] < 8 && image->pixels[i + 1] < 8 && image->pixels[i + 2] < 8;
  }
  EXPECT_LT(black, image->pixels.size() / 4 / 10) << "mostly black: still inside";
}

}  // namespace
}  // namespace globe::app
