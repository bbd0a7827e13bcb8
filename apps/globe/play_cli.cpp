// `globe play PYRAMID PATH --out DIR`: its options, their conversion into PlayOptions, and the
// summary it prints.
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "apps/globe/camera_argument.hpp"
#include "apps/globe/camera_track.hpp"
#include "apps/globe/play_command.hpp"
#include "apps/globe/subcommands.hpp"
#include "apps/globe/video_encoder.hpp"

namespace globe::app {
namespace {

struct PlayArguments {
  std::string pyramid;
  std::string path;
  std::string out;
  std::string size = "1280x720";
  std::string video;
  std::string exportCamera;
  std::string codec = "h264";
  std::optional<int> crf;
  bool resume = false;
  bool progress = false;
  std::string fps = "30";  // as text: checked and named by parseNumberArgument
  bool noFrames = false;
  bool noGlide = false;
  bool window = false;
  bool realTime = false;
  uint32_t morphFrames = 8;
  bool allowMissing = false;
};

int runPlayCommand(const PlayArguments& arguments, const CommonArguments& common,
                   const CommandContext& context) {
  auto size = parseSizeArgument(arguments.size);
  auto fps = parseNumberArgument("--fps", arguments.fps, 0, 1000, true);
  if (!size || !fps) {
    std::fprintf(stderr, "globe play: %s\n", (!size ? size.error() : fps.error()).c_str());
    return 2;
  }
  PlayOptions options;
  options.pyramid = arguments.pyramid;
  options.pathFile = arguments.path;
  options.outputDir = arguments.out;
  options.framesPerSecond = *fps;
  options.widthPixels = size->first;
  options.heightPixels = size->second;
  options.writeFrames = !arguments.noFrames;
  options.glide = !arguments.noGlide;
  options.window = arguments.window;
  options.realTime = arguments.realTime;
  options.morphFrames = arguments.morphFrames;
  if (!arguments.video.empty()) options.video = arguments.video;
  const auto codec = parseVideoCodec(arguments.codec);
  if (!codec) {
    std::fprintf(stderr, "globe play: --codec must be h264, h265 or prores, not '%s'\n",
                 arguments.codec.c_str());
    return 2;
  }
  if (arguments.crf && *codec == VideoCodec::ProRes) {
    std::fprintf(stderr, "globe play: --crf is for h264 and h265 (ProRes 422 HQ has no crf)\n");
    return 2;
  }
  options.videoSettings = {*codec, arguments.crf.value_or(18)};
  options.resume = arguments.resume;
  options.progress = arguments.progress;
  if (!arguments.exportCamera.empty()) {
    if (auto checked = checkCameraTrackPath(arguments.exportCamera); !checked) {
      std::fprintf(stderr, "globe play: %s\n", checked.error().c_str());
      return 2;
    }
    options.exportCamera = arguments.exportCamera;
  }
  if (!applySceneArguments("play", common, context, options.scene)) return 2;
  auto report = runPlay(options);
  if (!report) {
    std::fprintf(stderr, "globe play: %s\n", report.error().c_str());
    return 1;
  }
  std::fputs(report->summaryText.c_str(), stdout);
  if (report->failures > 0 && !arguments.allowMissing) {
    std::fprintf(stderr,
                 "globe play: %llu frame(s) lack tiles that failed to load (see above): they draw "
                 "coarser ground or imagery there; --allow-missing accepts that\n",
                 static_cast<unsigned long long>(report->failures));
    return 1;
  }
  return 0;
}

}  // namespace

Subcommand addPlayCommand(CLI::App& app, CommonArguments& common) {
  CLI::App* play = app.add_subcommand(
      "play",
      "play a camera path (.json or KML tour) through the collision controller, headless "
      "(OSMesa): frames, log.csv, timing.csv, summary.txt in --out");
  auto arguments = std::make_shared<PlayArguments>();
  addPyramidArgument(*play, arguments->pyramid, common);
  play->add_option("PATH", arguments->path, "camera path: .json keyframes or a .kml gx:Tour")
      ->required();
  play->add_option("--out", arguments->out, "output directory")->required();
  play->add_option("--fps", arguments->fps, "frames per second of path time (0..1000]")
      ->capture_default_str();
  play->add_option("--size", arguments->size, "WxH pixels")->capture_default_str();
  play->add_flag("--no-frames", arguments->noFrames, "write the logs only, no PNG frames");
  play->add_flag(
      "--no-glide", arguments->noGlide,
      "the paper's collision response alone: no lift over the ground ahead (docs/collision.md)");
  play->add_flag("--window", arguments->window, "show the playback in a GLFW window (same loop)");
  play->add_flag("--real-time", arguments->realTime,
                 "pace frames at --fps on the clock, each drawing the tiles arrived by then (as "
                 "globe view does): shows loading over a slow server; logs then vary run to run");
  play->add_option("--morph-frames", arguments->morphFrames,
                   "with --real-time: frames over which a finer tile arriving near the camera "
                   "rises out of the coarser ground (0: at once, a pop)")
      ->check(CLI::Range(0u, 1000u))
      ->capture_default_str();
  play->add_option("--video", arguments->video, "encode the frames into this MP4 with ffmpeg");
  play->add_option("--codec", arguments->codec,
                   "--video's codec: h264 (MP4, default), h265 (MP4) or prores (ProRes 422 HQ, "
                   "10-bit, in a QuickTime container whatever the name)");
  play->add_option("--crf", arguments->crf,
                   "--video's quality for h264 and h265: 0 (lossless) .. 51, default 18")
      ->check(CLI::Range(0, 51));
  play->add_flag("--resume", arguments->resume,
                 "keep the frames an interrupted run left in DIR/.frames-partial and render only "
                 "the rest (the path is replayed from its start: the same frames and log as an "
                 "uninterrupted run)");
  play->add_flag("--progress", arguments->progress,
                 "show the frames done and the time left on stderr");
  play->add_option("--export-camera", arguments->exportCamera,
                   "write the rendered camera of every frame: .json (geodetic, ECEF and a "
                   "quaternion), .csv (the same), or .jsx (an After Effects script: a keyed "
                   "two-node camera and nulls for the path's targets, in a local east-north-up "
                   "frame)")
      ->type_name("FILE");
  play->add_flag("--allow-missing", arguments->allowMissing,
                 "exit 0 even when tiles failed to load (drawn coarser; each named on stderr)");
  addGlobeOption(*play, common);
  addNetworkOptions(*play, common);
  addSeaFloorOption(*play, common);
  addLayerOptions(*play, common);
  return {play, [arguments, &common](const CommandContext& context) {
            return runPlayCommand(*arguments, common, context);
          }};
}

}  // namespace globe::app
