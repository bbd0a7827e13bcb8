// Failure is never silent: a pyramid whose blocks fail their CRC draws coarser tiles there, names
// each failed tile once on stderr, writes its image (or frames) and exits 1 unless
// --allow-missing says such a picture is fine. Before, a view whose tiles failed to decode exited
// 0 with nothing said.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "camera/camera_path_file.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/damaged_pyramid.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;

struct CommandRun {
  int exitCode = -1;
  std::string output;
};

CommandRun runGlobeCommand(const std::string& arguments, const fs::path& log) {
  const std::string command = std::string(GLOBE_EXE) + " " + arguments + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::stringstream text;
  text << std::ifstream(log).rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

TEST(MissingTiles, ASnapshotOrPlaybackWithFailedTilesSaysSoAndExitsOne) {
  const fs::path dir = globe::testing::freshTempDir("missing-tiles");
  const fs::path pyramid = globe::testing::damagedPyramid(dir);
  const std::string snapshot = "snapshot " + pyramid.string() +
                               " --camera 138.72,35.33,4500,20,-60,0 --size 320x180 -o " +
                               (dir / "view.png").string();
  const CommandRun strict = runGlobeCommand(snapshot, dir / "strict.txt");
  EXPECT_EQ(strict.exitCode, 1) << strict.output;
  EXPECT_TRUE(fs::exists(dir / "view.png")) << "the image is written all the same";
  EXPECT_NE(strict.output.find("fails its CRC"), std::string::npos) << strict.output;
  EXPECT_NE(strict.output.find("--allow-missing accepts such an image"), std::string::npos)
      << strict.output;
  // Each failed tile named once.
  std::vector<std::string> lines;
  for (std::stringstream in(strict.output); std::getline(in, lines.emplace_back());) {
  }
  std::sort(lines.begin(), lines.end());
  EXPECT_EQ(std::adjacent_find(lines.begin(), lines.end(),
                               [](const std::string& a, const std::string& b) {
                                 return a == b && !a.empty();
                               }),
            lines.end())
      << strict.output;
  const CommandRun allowed = runGlobeCommand(snapshot + " --allow-missing", dir / "allowed.txt");
  EXPECT_EQ(allowed.exitCode, 0) << allowed.output;
  EXPECT_NE(allowed.output.find("fails its CRC"), std::string::npos) << "said all the same";

  camera::CameraPathFile path;
  path.interpolation = "linear";
  path.keyframes = {{0.0, 138.72, 35.30, 6000, 20, -50, 0}, {1.0, 138.72, 35.33, 4500, 20, -60, 0}};
  ASSERT_TRUE(camera::writeCameraPathJson(dir / "path.json", path));
  const std::string play = "play " + pyramid.string() + " " + (dir / "path.json").string() +
                           " --fps 4 --size 160x90 --no-frames --out " + (dir / "play").string();
  const CommandRun played = runGlobeCommand(play, dir / "play.txt");
  EXPECT_EQ(played.exitCode, 1) << played.output;
  EXPECT_TRUE(fs::exists(dir / "play" / "log.csv")) << played.output;
  EXPECT_NE(played.output.find("--allow-missing accepts that"), std::string::npos)
      << played.output;
  EXPECT_EQ(runGlobeCommand(play + " --allow-missing", dir / "play2.txt").exitCode, 0);
}

}  // namespace
}  // namespace globe::app
