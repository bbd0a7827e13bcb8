// `globe play --resume` after a run was killed part-way: the frames it left are kept and the rest
// rendered, and the frames and the log equal an uninterrupted run's byte for byte; --codec and
// --crf encode what they say; --progress reports the frames and the time left.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>

#include <sys/wait.h>

#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;

std::string readWhole(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

int playFuji(const std::string& arguments, const fs::path& output, const std::string& prefix = "") {
  const std::string command = prefix + " " + std::string(GLOBE_EXE) + " play " +
                              globe::testing::bundledPyramid().string() + " " +
                              std::string(GLOBE_SOURCE_DIR) + "/data/paths/fuji-demo.json " +
                              arguments + " > " + output.string() + " 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(PlayResume, AResumedRunGivesTheFramesAndLogOfAnUninterruptedOne) {
  const fs::path dir = globe::testing::freshTempDir("play-resume");
  const std::string settings = " --fps 6 --size 120x68 --out ";
  ASSERT_EQ(playFuji(settings + (dir / "whole").string(), dir / "whole.txt"), 0)
      << readWhole(dir / "whole.txt");
  // Killed part-way (SIGKILL: no clean-up runs), then resumed.
  playFuji(settings + (dir / "cut").string(), dir / "cut.txt", "timeout -s KILL 0.8");
  const fs::path partial = dir / "cut" / ".frames-partial";
  size_t left = 0;
  if (fs::is_directory(partial)) {
    // Frames only: one being written when the run was killed is a temporary file.
    for (const auto& entry : fs::directory_iterator(partial)) {
      left += entry.path().extension() == ".png";
    }
  }
  // A simulated cut as well, so some frames are always kept whatever the machine's speed.
  fs::create_directories(dir / "copy" / ".frames-partial");
  for (const char* name : {"00000.png", "00001.png", "00002.png", "00003.png", "00004.png"}) {
    fs::copy_file(dir / "whole" / "frames" / name, dir / "copy" / ".frames-partial" / name);
  }
  for (const std::string run : {"cut", "copy"}) {
    ASSERT_EQ(playFuji(settings + (dir / run).string() + " --resume --progress", dir / (run + ".txt")),
              0)
        << readWhole(dir / (run + ".txt"));
    const std::string output = readWhole(dir / (run + ".txt"));
    EXPECT_NE(output.find("resumed: " + std::to_string(run == "copy" ? 5 : left) + " frame(s)"),
              std::string::npos)
        << output;
    EXPECT_NE(output.find("frame 169/169 (100 %)"), std::string::npos) << output;
    EXPECT_EQ(readWhole(dir / run / "log.csv"), readWhole(dir / "whole" / "log.csv")) << run;
    size_t frames = 0;
    for (const auto& entry : fs::directory_iterator(dir / "whole" / "frames")) {
      ++frames;
      EXPECT_EQ(readWhole(dir / run / "frames" / entry.path().filename()), readWhole(entry.path()))
          << run << " " << entry.path().filename();
    }
    EXPECT_EQ(frames, 169u);
    size_t written = 0;
    for (const auto& entry : fs::directory_iterator(dir / run / "frames")) {
      written += 1;
      EXPECT_EQ(entry.path().extension(), ".png") << entry.path();
    }
    EXPECT_EQ(written, 169u) << "no stray files among the frames";
    EXPECT_FALSE(fs::exists(partial)) << "renamed to frames/ once complete";
  }
  std::printf("the killed run had left %zu frames\n", left);
}

TEST(PlayResume, TheCodecAndQualityAreWhatTheOptionsSay) {
  if (std::system("command -v ffprobe > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "ffmpeg is not installed: the codecs were not tested";
  }
  const fs::path dir = globe::testing::freshTempDir("play-codecs");
  for (const auto& [codec, file, stream] :
       {std::tuple{"h265 --crf 30", "v.mp4", "hevc,yuv420p"},
        std::tuple{"prores", "v.mov", "prores,yuv422p10le"},
        std::tuple{"h264", "v2.mp4", "h264,yuv420p"}}) {
    const std::string arguments = " --fps 1 --size 96x54 --out " + (dir / "out").string() +
                                  " --video " + (dir / file).string() + " --codec " + codec;
    ASSERT_EQ(playFuji(arguments, dir / "codec.txt"), 0) << readWhole(dir / "codec.txt");
    const std::string probe = "ffprobe -v error -show_entries stream=codec_name,pix_fmt -of csv=p=0 " +
                              (dir / file).string() + " > " + (dir / "probe.txt").string();
    ASSERT_EQ(std::system(probe.c_str()), 0);
    EXPECT_EQ(readWhole(dir / "probe.txt"), std::string(stream) + "\n") << codec;
  }
  EXPECT_EQ(playFuji(" --fps 1 --size 96x54 --out " + (dir / "x").string() + " --codec av1",
                 dir / "bad.txt"),
            2);
  EXPECT_NE(readWhole(dir / "bad.txt").find("--codec must be h264, h265 or prores, not 'av1'"),
            std::string::npos);
  EXPECT_EQ(playFuji(" --fps 1 --size 96x54 --out " + (dir / "x").string() + " --codec prores --crf 20",
                 dir / "bad2.txt"),
            2);
}

}  // namespace
}  // namespace globe::app
