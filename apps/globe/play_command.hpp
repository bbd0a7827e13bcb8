// `globe play`: deterministic playback of a camera path through the collision controller, headless
// (OSMesa) or in a window, writing frames, a per-frame log, timings, a summary and a video.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "apps/globe/play_log.hpp"
#include "apps/globe/video_encoder.hpp"
#include "scene/terrain_scene.hpp"

namespace globe::app {

struct PlayOptions {
  std::filesystem::path pyramid;
  std::filesystem::path pathFile;  // .json or .kml
  std::filesystem::path outputDir;
  double framesPerSecond = 30;
  int widthPixels = 1280, heightPixels = 720;
  bool writeFrames = true;
  bool glide = true;    // the controller glides over the ground ahead (camera/terrain_glide.hpp)
  bool window = false;  // a GLFW window instead of OSMesa
  // Frames paced at fps on the clock, each drawing what has arrived by then (PlaybackStep's real
  // time), finer tiles near the camera morphing in (SceneOptions::morphFrames): the flight as a
  // window would show it over this pyramid and network. The log then depends on the timing.
  bool realTime = false;
  uint32_t morphFrames = 8;  // with realTime: SceneOptions::morphFrames (0: tiles pop in at once)
  std::optional<std::filesystem::path> video;  // encode the frames with ffmpeg
  VideoSettings videoSettings;                  // --codec, --crf
  // --resume: frames a killed or failed run left in DIR/.frames-partial are kept (not read back
  // or written again); the path is played from its start all the same, so the camera, the log and
  // the new frames are those of an uninterrupted run.
  bool resume = false;
  bool progress = false;  // --progress: a line on stderr as frames are done, with the time left
  // --export-camera: the rendered camera of every frame (apps/globe/camera_track.hpp).
  std::optional<std::filesystem::path> exportCamera;
  scene::SceneOptions scene;
  int timeoutSeconds = 300;  // for each frame's view to complete
};

struct PlayReport {
  PlaySummary summary;
  std::string summaryText;    // as printed and written to DIR/summary.txt
  bool stoppedEarly = false;  // the window was closed before the path's end
  uint64_t failures = 0;      // frames whose view lacks tiles that failed to load (named on stderr)
};

// Frame i shows the path at start + i / fps, up to its end. Each frame: the scripted pose is
// proposed to the controller, which runs QOTCD and the response against the previous frame's
// complete rendering tile array; the scene then selects and loads the tiles for the corrected
// pose until the view is complete (no hysteresis), and the controller runs once more against that
// array with dt = 0 (the hard floor and the near-plane push, should finer terrain have risen
// under it) until the pose no longer changes; the renderer draws exactly that array. The first
// frame's view is made complete at the scripted pose before anything runs. Outputs (DIR):
// frames/NNNNN.png (replaced as a whole at the end; removed with writeFrames off), log.csv,
// timing.csv, summary.txt (each written atomically at the end); nothing of a failed run is left
// but what an earlier run wrote. Errors: the path file, the pyramid, the output directory, GL,
// ffmpeg missing (checked before rendering) or failing.
Result<PlayReport> runPlay(const PlayOptions& options);

}  // namespace globe::app
