// The `globe play` frame loop: PlaybackStep (scripted pose → controller against the complete
// drawn array → complete view for the corrected pose) → draw → frame, log row.
#include "apps/globe/play_command.hpp"
#include "apps/globe/model_drawing.hpp"

#include "apps/globe/camera_track.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <system_error>
#include <thread>

#include "apps/globe/elapsed.hpp"
#include "apps/globe/overlay_drawing.hpp"
#include "apps/globe/path_conversion.hpp"
#include "apps/globe/playback_step.hpp"
#include "apps/globe/renderer_gpu.hpp"
#include "apps/globe/video_encoder.hpp"
#include "camera/camera_path.hpp"
#include "camera/camera_path_file.hpp"
#include "formats/image_io.hpp"
#include "render/glfw_window_context.hpp"
#include "render/multisample_target.hpp"
#include "render/osmesa_context.hpp"
#include "render/read_pixels.hpp"
#include "transport/atomic_file.hpp"

namespace globe::app {
namespace {

using Clock = std::chrono::steady_clock;
constexpr long kMaximumFrames = 10'000'000;

// Where frames are written until the run completes (then renamed to DIR/frames): a killed or
// failed run leaves them there for --resume; a run without it starts afresh.
constexpr const char* kPartialFrames = ".frames-partial";

Result<void> preparePartialFrames(const std::filesystem::path& partial, bool resume) {
  std::error_code error;
  if (!resume) std::filesystem::remove_all(partial, error);
  std::filesystem::create_directories(partial, error);
  if (error) return makeError("cannot create " + partial.string() + ": " + error.message());
  // A frame being written when the run was killed is a temporary file: not a frame, removed.
  for (const auto& entry : std::filesystem::directory_iterator(partial, error)) {
    if (entry.path().extension() != ".png") std::filesystem::remove(entry.path(), error);
  }
  return {};
}

// "frame 120/841 (14 %), 12.3 s, about 61 s left" on stderr: in place on a terminal, else a line
// every 5 % (logs stay short).
void printProgress(int done, int total, double elapsedSeconds) {
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  const int step = std::max(1, total / 20);
  if (!terminal && done % step != 0 && done != total) return;
  const double left = done > 0 ? elapsedSeconds * (total - done) / done : 0.0;
  std::fprintf(stderr, "%sframe %d/%d (%d %%), %.1f s, about %.0f s left%s", terminal ? "\r" : "",
               done, total, 100 * done / std::max(total, 1), elapsedSeconds, left,
               terminal && done < total ? "" : "\n");
  std::fflush(stderr);
}

Result<void> prepareOutputDirectory(const std::filesystem::path& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error)
    return makeError("cannot create the output directory " + dir.string() + ": " + error.message());
  const std::filesystem::path probe = dir / (".globe-play-probe-" + std::to_string(::getpid()));
  if (auto written = transport::writeFileAtomically(probe, std::string_view("")); !written) {
    return makeError("the output directory is not writable: " + written.error());
  }
  std::filesystem::remove(probe, error);
  return {};
}

// The GL surface frames are drawn on: OSMesa, or a window shown as the path plays.
struct Surface {
  std::unique_ptr<render::OsMesaContext> offscreen;
  std::unique_ptr<render::GlfwWindowContext> window;
  int widthPixels = 0, heightPixels = 0;
};

Result<Surface> openSurface(const PlayOptions& options) {
  Surface surface;
  if (options.window) {
    render::GlfwWindowOptions windowOptions;
    windowOptions.widthPixels = options.widthPixels;
    windowOptions.heightPixels = options.heightPixels;
    windowOptions.title = "globe play";
    windowOptions.vsync = false;  // playback runs as fast as the views complete
    auto window = render::GlfwWindowContext::create(windowOptions);
    if (!window) {
      return makeError("cannot open a window (no display? drop --window or run under xvfb-run): " +
                       window.error());
    }
    surface.window = std::move(*window);
    surface.widthPixels = surface.window->framebufferWidthPixels();
    surface.heightPixels = surface.window->framebufferHeightPixels();
  } else {
    auto context = render::OsMesaContext::create(options.widthPixels, options.heightPixels);
    if (!context) return Error{context.error()};
    surface.offscreen = std::move(*context);
    surface.widthPixels = options.widthPixels;
    surface.heightPixels = options.heightPixels;
  }
  return surface;
}

}  // namespace

Result<PlayReport> runPlay(const PlayOptions& options) {
  const auto runStart = Clock::now();
  // Everything that can be refused is checked before anything is written.
  if (!(std::isfinite(options.framesPerSecond) && options.framesPerSecond > 0 &&
        options.framesPerSecond <= 1000)) {
    char text[64];
    std::snprintf(text, sizeof text, "--fps %g: must be in (0, 1000]", options.framesPerSecond);
    return makeError(text);
  }
  std::optional<std::filesystem::path> ffmpeg;
  if (options.video) {
    if (!options.writeFrames) return makeError("--video needs the frames: drop --no-frames");
    ffmpeg = findExecutable("ffmpeg");
    if (!ffmpeg) {
      return makeError(
          "--video needs the ffmpeg program on PATH (Debian: apt-get install "
          "ffmpeg); nothing was rendered");
    }
  }
  scene::SceneOptions sceneOptions = options.scene;
  if (options.realTime) {
    sceneOptions.morphFrames = options.morphFrames;
    sceneOptions.shadowTilesPerFrame = 4;  // as the window does: a frame's time stays bounded
  }
  auto playback = openScriptedPlayback(options.pyramid, options.pathFile, sceneOptions);
  if (!playback) return Error{playback.error()};
  scene::TerrainScene& scene = *playback->scene;
  const camera::CameraPath& path = playback->path;
  const double fps = options.framesPerSecond;
  const double duration = path.endSeconds() - path.startSeconds();
  const double frameCount = playbackFrameCount(duration, fps);
  if (!(frameCount <= static_cast<double>(kMaximumFrames))) {
    return makeError("the path is " + std::to_string(duration) + " s long: more than " +
                     std::to_string(kMaximumFrames) + " frames at this --fps");
  }
  const int frames = static_cast<int>(frameCount);

  if (auto prepared = prepareOutputDirectory(options.outputDir); !prepared) {
    return Error{prepared.error()};
  }
  const std::filesystem::path framesDir = options.outputDir / "frames";
  const std::filesystem::path partial = options.outputDir / kPartialFrames;
  if (options.writeFrames) {
    if (auto prepared = preparePartialFrames(partial, options.resume); !prepared) {
      return Error{prepared.error()};
    }
  }

  auto surface = openSurface(options);
  if (!surface) return Error{surface.error()};
  render::TerrainRendererOptions rendererOptions;
  rendererOptions.warn = options.scene.warnings;  // no sky, layers this GL cannot compile
  rendererOptions.verticesPerSide = scene.store().manifest().verticesPerSide;
  auto renderer = render::TerrainRenderer::create(rendererOptions);
  if (!renderer) return Error{renderer.error()};
  RendererGpu gpu(**renderer, options.scene);
  auto labels = OverlayDrawing::create(scene);
  if (!labels) return Error{labels.error()};
  auto models = ModelDrawing::create(scene);
  if (!models) return Error{models.error()};
  const int width = surface->widthPixels, height = surface->heightPixels;
  auto target = render::multisampleTargetFor(width, height, options.scene.samples);
  if (!target) return Error{target.error()};
  PlaybackStep step(scene, gpu, path, width, height, std::chrono::seconds(options.timeoutSeconds),
                    options.glide, options.realTime);
  // The first collision test runs against a complete view at the scripted start.
  FrameTimings startup;
  if (auto view = step.start(startup); !view) return Error{view.error()};
  const auto loopStart = Clock::now();

  PlayReport report;
  std::vector<FrameRecord> records;
  int resumedFrames = 0;  // frames --resume found written
  for (int i = 0; i < frames; ++i) {
    if (options.realTime) {
      std::this_thread::sleep_until(loopStart + std::chrono::duration_cast<Clock::duration>(
                                                    std::chrono::duration<double>(i / fps)));
    }
    const auto frameStart = Clock::now();
    // Time from the frame number, never accumulated: frame i is exactly start + i / fps.
    auto stepped =
        step.frame(i, path.startSeconds() + static_cast<double>(i) / fps, i == 0 ? 0.0 : 1.0 / fps);
    if (!stepped) return Error{stepped.error()};
    FrameRecord& record = *stepped;

    const auto drawStart = Clock::now();
    if (*target) (*target)->bind();
    const render::FrameStats stats = gpu.draw(scene);
    if (*models) (*models)->draw(scene);
    if (*labels) (*labels)->draw(scene);
    if (*target) (*target)->resolve();
    record.tilesDrawn = stats.tilesDrawn;
    record.imageryTextureBytes = stats.imageryBytesResident;
    char name[32];
    std::snprintf(name, sizeof name, "%05d.png", i);
    // A frame an interrupted run wrote (atomically: complete) is kept as it is.
    const bool kept =
        options.writeFrames && options.resume && std::filesystem::is_regular_file(partial / name);
    resumedFrames += kept ? 1 : 0;
    std::vector<uint8_t> pixels;
    if (options.writeFrames && !kept) {
      pixels = render::readPixelsRgba(width, height);
    } else {
      render::finishGl();
    }
    record.timings.drawMs = millisecondsSince(drawStart);
    if (options.writeFrames && !kept) {
      const auto writeStart = Clock::now();
      if (auto written = formats::writePngAtomically(partial / name, pixels, width, height);
          !written) {
        return Error{written.error()};
      }
      record.timings.writeMs = millisecondsSince(writeStart);
    }
    if (options.progress) printProgress(i + 1, frames, millisecondsSince(loopStart) / 1000.0);
    if (surface->window) {
      surface->window->swapBuffers();
      surface->window->pollEvents();
    }
    record.timings.totalMs = millisecondsSince(frameStart);
    records.push_back(record);
    if (surface->window && surface->window->shouldClose()) {
      report.stoppedEarly = i + 1 < frames;
      break;
    }
  }

  // The outputs, each complete: the frames directory replaced as a whole, then the logs.
  std::error_code error;
  std::filesystem::remove_all(framesDir, error);
  if (error) return makeError("cannot replace " + framesDir.string() + ": " + error.message());
  if (options.writeFrames) {
    std::filesystem::rename(partial, framesDir, error);
    if (error)
      return makeError("cannot rename the frames to " + framesDir.string() + ": " +
                       error.message());
  }
  report.summary = summarize(records);
  for (const FrameRecord& record : records) report.failures += record.missingTiles > 0 ? 1 : 0;
  if (!options.scene.layers.empty()) {
    report.summary.imageryTextureBudgetBytes = options.scene.imageryBudget.textureBytes;
  }
  char header[512];
  std::snprintf(header, sizeof header, "globe play %s: %dx%d at %g fps%s\n",
                options.pathFile.string().c_str(), width, height, fps,
                report.stoppedEarly ? " (window closed: stopped early)" : "");
  std::string outputs = "log: " + (options.outputDir / "log.csv").string() +
                        "\ntiming: " + (options.outputDir / "timing.csv").string() + "\n";
  if (options.writeFrames) {
    char last[32];
    std::snprintf(last, sizeof last, "%05zu.png", records.size() - 1);
    outputs += "frames: " + (framesDir / "00000.png").string() + " ... " + last + "\n";
  }
  if (options.video) outputs += "video: " + options.video->string() + "\n";
  if (options.exportCamera) outputs += "camera: " + options.exportCamera->string() + "\n";
  if (options.resume) {
    outputs += "resumed: " + std::to_string(resumedFrames) + " frame(s) kept from " +
               (options.outputDir / kPartialFrames).string() + "\n";
  }
  char wall[96];
  std::snprintf(wall, sizeof wall, "wall time: %.1f s\n", millisecondsSince(runStart) / 1000.0);
  report.summaryText = header + formatSummary(report.summary, records) + wall + outputs;
  const std::pair<const char*, std::string> texts[] = {{"log.csv", formatPlayLog(records)},
                                                       {"timing.csv", formatTimingLog(records)},
                                                       {"summary.txt", report.summaryText}};
  for (const auto& [name, text] : texts) {
    if (auto written = transport::writeFileAtomically(options.outputDir / name, text); !written) {
      return Error{written.error()};
    }
  }
  if (options.exportCamera) {
    CameraTrackSettings track{fps, width, height, {}};
    for (const camera::CameraKeyframe& key : path.keyframes) {
      if (key.targetEcefMeters) track.targetsEcefMeters.push_back(*key.targetEcefMeters);
    }
    auto text = formatCameraTrack(*options.exportCamera, records, track, scene.ellipsoid());
    if (!text) return Error{text.error()};
    if (auto written = transport::writeFileAtomically(*options.exportCamera, *text); !written) {
      return Error{written.error()};
    }
  }
  if (options.video) {
    if (auto encoded = encodeVideo(*ffmpeg, framesDir, fps, *options.video, options.videoSettings);
        !encoded) {
      return Error{encoded.error()};
    }
  }
  return report;
}

}  // namespace globe::app
