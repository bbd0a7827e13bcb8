// The `globe play` frame loop: scripted pose → controller against the complete drawn array →
// complete view for the corrected pose → draw → frame, log row.
#include "app/play_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <system_error>

#include "app/finest_surface.hpp"
#include "app/path_conversion.hpp"
#include "app/video_encoder.hpp"
#include "camera/camera_controller.hpp"
#include "camera/camera_path.hpp"
#include "collision/exact_surface.hpp"
#include "io/atomic_file.hpp"
#include "io/camera_path_file.hpp"
#include "io/image_io.hpp"
#include "render/glfw_window_context.hpp"
#include "render/osmesa_context.hpp"
#include "render/read_pixels.hpp"

namespace globe::app {
namespace {

using Clock = std::chrono::steady_clock;
constexpr int kMaximumSettleRounds = 8;
constexpr long kMaximumFrames = 10'000'000;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A directory removed on scope exit unless kept: frames of a run that fails never remain.
class PartialDirectory {
 public:
  explicit PartialDirectory(std::filesystem::path path) : path_(std::move(path)) {}
  ~PartialDirectory() {
    std::error_code ignored;
    if (!kept_) std::filesystem::remove_all(path_, ignored);
  }
  PartialDirectory(const PartialDirectory&) = delete;
  PartialDirectory& operator=(const PartialDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }
  void keep() { kept_ = true; }

 private:
  std::filesystem::path path_;
  bool kept_ = false;
};

Result<void> prepareOutputDirectory(const std::filesystem::path& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error)
    return makeError("cannot create the output directory " + dir.string() + ": " + error.message());
  const std::filesystem::path probe = dir / (".globe-play-probe-" + std::to_string(::getpid()));
  if (auto written = io::writeFileAtomically(probe, std::string_view("")); !written) {
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

class Player {
 public:
  Player(const PlayOptions& options, TerrainScene& scene, render::TerrainRenderer& renderer,
         const Surface& surface)
      : options_(options), scene_(scene), renderer_(renderer), surface_(surface) {}

  // Updates the scene for the pose until every tile it needs is loaded.
  Result<void> completeView(const camera::CameraPose& pose, FrameTimings& timings) {
    const auto until = Clock::now() + std::chrono::seconds(options_.timeoutSeconds);
    for (;;) {
      const auto start = Clock::now();
      const FrameInfo info =
          scene_.update(pose, surface_.widthPixels, surface_.heightPixels, renderer_);
      timings.selectMs += msSince(start);
      if (info.complete) return {};
      if (Clock::now() > until) {
        return makeError("the view was not complete after " +
                         std::to_string(options_.timeoutSeconds) + " s (" +
                         std::to_string(info.requests) + " tiles still wanted)");
      }
      const auto wait = Clock::now();
      scene_.waitForLoads(std::chrono::milliseconds(50));
      timings.loadMs += msSince(wait);
    }
  }

  // One controller update against the scene's current (complete) array, folded into the record.
  void collide(camera::CameraController& controller, double dtSeconds, FrameRecord& record) {
    const auto start = Clock::now();
    const camera::CollisionState& state =
        controller.update(dtSeconds, scene_.renderingTileArray(), scene_.ellipsoid());
    record.timings.collisionMs += msSince(start);
    record.collided = record.collided || state.collided;
    if (record.response == collision::Response::None) record.response = state.response;
  }

 private:
  const PlayOptions& options_;
  TerrainScene& scene_;
  render::TerrainRenderer& renderer_;
  const Surface& surface_;
};

}  // namespace

Result<PlayReport> runPlay(const PlayOptions& options) {
  const auto runStart = Clock::now();
  // Everything that can be refused is checked before anything is written.
  auto file = io::readCameraPath(options.pathFile);
  if (!file) return Error{file.error()};
  if (!(std::isfinite(options.framesPerSecond) && options.framesPerSecond > 0 &&
        options.framesPerSecond <= 1000)) {
    return makeError("--fps must be in (0, 1000]");
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
  SceneOptions sceneOptions = options.scene;
  sceneOptions.hysteresis = false;  // each view depends on its pose only, not on the load order
  auto scene = TerrainScene::open(options.pyramid, sceneOptions);
  if (!scene) return Error{scene.error()};
  auto path = toCameraPath(
      *file, [&](double lon, double lat) { return (*scene)->terrainHeightMeters(lon, lat); });
  if (!path) return makeError(options.pathFile.string() + ": " + path.error());
  const double fps = options.framesPerSecond;
  const double duration = path->endSeconds() - path->startSeconds();
  const double frameCount = std::floor(duration * fps + 1e-9) + 1;
  if (frameCount > static_cast<double>(kMaximumFrames)) {
    return makeError("the path is " + std::to_string(duration) + " s long: more than " +
                     std::to_string(kMaximumFrames) + " frames at this --fps");
  }
  const int frames = static_cast<int>(frameCount);

  if (auto prepared = prepareOutputDirectory(options.outputDir); !prepared) {
    return Error{prepared.error()};
  }
  const std::filesystem::path framesDir = options.outputDir / "frames";
  PartialDirectory partial(options.outputDir / (".frames-partial-" + std::to_string(::getpid())));
  if (options.writeFrames) {
    std::error_code error;
    std::filesystem::remove_all(partial.path(), error);
    std::filesystem::create_directories(partial.path(), error);
    if (error)
      return makeError("cannot create " + partial.path().string() + ": " + error.message());
  }

  auto surface = openSurface(options);
  if (!surface) return Error{surface.error()};
  auto renderer = render::TerrainRenderer::create({});
  if (!renderer) return Error{renderer.error()};
  const geo::Ellipsoid& ellipsoid = (*scene)->ellipsoid();
  const int width = surface->widthPixels, height = surface->heightPixels;
  Player player(options, **scene, **renderer, *surface);
  FinestSurface finestSurface((*scene)->store(), ellipsoid);

  const camera::CameraPose first = camera::samplePath(*path, path->startSeconds(), ellipsoid);
  camera::CameraController controller(first);
  controller.setNearPlane({camera::projectionForHeight(0, controller.settings().clearance.eyeMeters,
                                                       sceneOptions.fovYRadians, 1, ellipsoid)
                               .nearMeters,
                           sceneOptions.fovYRadians,
                           static_cast<double>(width) / std::max(height, 1)});
  // The first collision test runs against a complete view at the scripted start.
  FrameTimings startup;
  if (auto view = player.completeView(first, startup); !view) return Error{view.error()};

  PlayReport report;
  std::vector<FrameRecord> records;
  for (int i = 0; i < frames; ++i) {
    const auto frameStart = Clock::now();
    FrameRecord record;
    record.frame = i;
    record.timeSeconds = path->startSeconds() + static_cast<double>(i) / fps;
    const camera::CameraPose scripted = camera::samplePath(*path, record.timeSeconds, ellipsoid);
    record.scriptedHeightMeters = scripted.position.heightMeters;
    // The move, against the array drawn last frame (complete, so the same on every run).
    controller.propose(scripted);
    player.collide(controller, i == 0 ? 0.0 : 1.0 / fps, record);
    // The view for the corrected pose, and the controller once more against that array (dt 0:
    // the floor and the near-plane push only) until it keeps the pose.
    bool settled = false;
    for (int round = 0; round < kMaximumSettleRounds && !settled; ++round) {
      if (auto view = player.completeView(controller.pose(), record.timings); !view) {
        return Error{view.error()};
      }
      const camera::CameraPose before = controller.pose();
      player.collide(controller, 0.0, record);
      settled = camera::samePose(before, controller.pose());
    }
    if (!settled) {
      if (auto view = player.completeView(controller.pose(), record.timings); !view) {
        return Error{view.error()};
      }
    }
    record.pose = controller.pose();
    const auto surfaceHeight = collision::exactSurfaceHeight(
        (*scene)->renderingTileArray(), ellipsoid, record.pose.position.longitudeRadians,
        record.pose.position.latitudeRadians);
    if (surfaceHeight) {
      record.terrainHeightMeters = surfaceHeight->heightMeters;
      const std::vector<geo::TileId>& drawn = (*scene)->tiles();
      record.terrainSource =
          std::find(drawn.begin(), drawn.end(), surfaceHeight->tile) != drawn.end()
              ? TerrainSource::Drawn
              : TerrainSource::Nadir;
    } else {
      record.terrainSource = TerrainSource::Finest;
      auto finest = finestSurface.heightMeters(record.pose.position.longitudeRadians,
                                               record.pose.position.latitudeRadians);
      if (!finest) return Error{finest.error()};
      record.terrainHeightMeters = *finest;
    }
    record.clearanceMeters = record.pose.position.heightMeters - record.terrainHeightMeters;
    record.nearClearanceMeters = controller.state().nearPlaneClearanceMeters;

    const auto drawStart = Clock::now();
    const render::FrameStats stats = (*scene)->draw(**renderer);
    record.tilesDrawn = stats.tilesDrawn;
    std::vector<uint8_t> pixels;
    if (options.writeFrames) {
      pixels = render::readPixelsRgba(width, height);
    } else {
      render::finishGl();
    }
    record.timings.drawMs = msSince(drawStart);
    if (options.writeFrames) {
      const auto writeStart = Clock::now();
      char name[32];
      std::snprintf(name, sizeof name, "%05d.png", i);
      if (auto written = io::writePngAtomically(partial.path() / name, pixels, width, height);
          !written) {
        return Error{written.error()};
      }
      record.timings.writeMs = msSince(writeStart);
    }
    if (surface->window) {
      surface->window->swapBuffers();
      surface->window->pollEvents();
    }
    record.timings.totalMs = msSince(frameStart);
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
    std::filesystem::rename(partial.path(), framesDir, error);
    if (error)
      return makeError("cannot rename the frames to " + framesDir.string() + ": " +
                       error.message());
    partial.keep();
  }
  report.summary = summarize(records);
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
  char wall[96];
  std::snprintf(wall, sizeof wall, "wall time: %.1f s\n", msSince(runStart) / 1000.0);
  report.summaryText = header + formatSummary(report.summary, records) + wall + outputs;
  const std::pair<const char*, std::string> texts[] = {{"log.csv", formatPlayLog(records)},
                                                       {"timing.csv", formatTimingLog(records)},
                                                       {"summary.txt", report.summaryText}};
  for (const auto& [name, text] : texts) {
    if (auto written = io::writeFileAtomically(options.outputDir / name, text); !written) {
      return Error{written.error()};
    }
  }
  if (options.video) {
    if (auto encoded = encodeVideo(*ffmpeg, framesDir, fps, *options.video); !encoded) {
      return Error{encoded.error()};
    }
  }
  return report;
}

}  // namespace globe::app
