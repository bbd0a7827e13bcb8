// globe-bench-tileset-frames: what a 3D Tiles tileset costs the frames that draw it, in one
// process and one GL context (OSMesa), against the same views without it.
//
// 1. Steady frames: each view's scene complete (terrain and the tileset's contents), then frames
//    of update + draw (terrain, then the contents: app::ModelDrawing, as the viewer) + glFinish,
//    the sides' rounds interleaved so both see the same machine load; medians.
// 2. A flight towards the tileset from far, as `globe view` runs it: one update + draw + glFinish
//    a frame, never waiting for loads (hysteresis on, 8 morph frames), every flight a fresh scene
//    and renderer (nothing loaded), the sides alternated flight by flight. Per flight the median
//    frame, its 99th percentile and the longest frame, and the frames in which 3D tile contents
//    arrived (a content id drawn that the frame before did not draw: its decoding and height grid
//    were made on the loader threads, its GL upload in this frame). The point: those frames are
//    not longer than the others by the decoding.
//
// The camera path is made before anything is timed: from the start pose to the last view,
// position and height eased together (the height geometrically), every pose kept at least 60 m
// above the pyramid's finest ground (read from a scene of its own). A table printer, not a test.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

#include "apps/globe/camera_argument.hpp"
#include "apps/globe/model_drawing.hpp"
#include "apps/globe/renderer_gpu.hpp"
#include "apps/globe/stderr_warnings.hpp"
#include "formats/image_io.hpp"
#include "render/osmesa_context.hpp"
#include "render/read_pixels.hpp"
#include "scene/terrain_scene.hpp"
#include "tiles3d/tileset.hpp"
#include "transport/atomic_file.hpp"

namespace {

using namespace globe;
using Clock = std::chrono::steady_clock;

struct Side {
  std::unique_ptr<render::TerrainRenderer> renderer;
  std::unique_ptr<app::RendererGpu> gpu;  // over renderer
  std::unique_ptr<scene::TerrainScene> scene;
  std::unique_ptr<app::ModelDrawing> models;  // null without a tileset
  std::vector<double> frameMs;
  uint64_t terrainTriangles = 0, modelTriangles = 0;
  size_t modelsDrawn = 0;
};

struct FrameResult {
  double ms = 0;
  size_t contentsArrived = 0;  // ids drawn this frame that the frame before did not draw
};

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::nth_element(values.begin(), values.begin() + static_cast<long>(values.size() / 2),
                   values.end());
  return values[values.size() / 2];
}

// The value at or below which `fraction` of the values lie (nearest rank).
double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const size_t rank = static_cast<size_t>(std::ceil(fraction * static_cast<double>(values.size())));
  return values[std::clamp<size_t>(rank, 1, values.size()) - 1];
}

double maximum(const std::vector<double>& values) {
  return values.empty() ? 0 : *std::max_element(values.begin(), values.end());
}

scene::SceneOptions sceneOptions(const std::shared_ptr<const tiles3d::Tileset>& tileset,
                                 bool asTheWindow) {
  scene::SceneOptions options;
  options.warnings = app::stderrWarnings();
  if (tileset) options.tilesets.push_back(tileset);
  if (asTheWindow) {  // apps/globe/view_cli.cpp
    options.morphFrames = 8;
    options.shadowTilesPerFrame = 4;
  } else {
    options.hysteresis = false;  // a steady view's tiles depend on the view only
  }
  return options;
}

Result<Side> openSide(const std::string& pyramid,
                      const std::shared_ptr<const tiles3d::Tileset>& tileset, bool asTheWindow) {
  Side side;
  const scene::SceneOptions options = sceneOptions(tileset, asTheWindow);
  auto scene = scene::TerrainScene::open(pyramid, options);
  if (!scene) return Error{scene.error()};
  side.scene = std::move(*scene);
  render::TerrainRendererOptions rendererOptions;
  rendererOptions.warn = options.warnings;
  rendererOptions.verticesPerSide = side.scene->store().manifest().verticesPerSide;
  auto renderer = render::TerrainRenderer::create(rendererOptions);
  if (!renderer) return Error{renderer.error()};
  side.renderer = std::move(*renderer);
  side.gpu = std::make_unique<app::RendererGpu>(*side.renderer, options);
  auto models = app::ModelDrawing::create(*side.scene);
  if (!models) return Error{models.error()};
  side.models = std::move(*models);
  return side;
}

// One frame as the viewer runs it: update (selection, polls), draw the terrain and the
// contents, glFinish.
double timeFrame(Side& side, const camera::CameraPose& pose, int width, int height) {
  const auto start = Clock::now();
  side.scene->update(pose, width, height, *side.gpu);
  const render::FrameStats stats = side.gpu->draw(*side.scene);
  if (side.models) side.models->draw(*side.scene);
  render::finishGl();
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  side.terrainTriangles = stats.triangles;
  side.modelTriangles = side.models ? side.models->trianglesDrawn() : 0;
  side.modelsDrawn = side.scene->drawnModels().size();
  return ms;
}

Result<void> writePng(const std::string& path, int width, int height) {
  const std::vector<uint8_t> pixels = render::readPixelsRgba(width, height);
  return formats::writePngAtomically(path, pixels, width, height);
}

struct NamedPose {
  std::string name;
  camera::CameraPose pose;
};

Result<NamedPose> parseView(const std::string& text) {
  const size_t equals = text.find('=');
  if (equals == std::string::npos) return makeError("--view " + text + ": expected NAME=CAMERA");
  auto pose = app::parseCameraArgument(text.substr(equals + 1));
  if (!pose) return makeError("--view " + text + ": " + pose.error());
  return NamedPose{text.substr(0, equals), *pose};
}

double lerp(double a, double b, double t) { return a + (b - a) * t; }

// From `from` to `to` in `frames` poses (the last one `to` exactly): the height geometric, the
// position following the height (most of the way covered while the camera is high, as a fly-to
// does), heading and pitch linear; every pose but the last at least `clearance` above the ground.
Result<std::vector<camera::CameraPose>> flightPath(const std::string& pyramid,
                                                   const camera::CameraPose& from,
                                                   const camera::CameraPose& to, int frames,
                                                   double clearanceMeters) {
  scene::SceneOptions options;
  options.warnings = app::stderrWarnings();
  auto ground = scene::TerrainScene::open(pyramid, options);
  if (!ground) return Error{ground.error()};
  std::vector<camera::CameraPose> path;
  const double h0 = from.position.heightMeters, h1 = to.position.heightMeters;
  for (int i = 0; i < frames; ++i) {
    const double t = frames > 1 ? static_cast<double>(i) / (frames - 1) : 1.0;
    camera::CameraPose pose = to;
    if (i + 1 < frames) {
      const double height = h0 * std::pow(h1 / h0, t);
      const double s = h0 != h1 ? (h0 - height) / (h0 - h1) : t;
      pose.position.longitudeRadians =
          lerp(from.position.longitudeRadians, to.position.longitudeRadians, s);
      pose.position.latitudeRadians =
          lerp(from.position.latitudeRadians, to.position.latitudeRadians, s);
      pose.position.heightMeters = height;
      pose.headingRadians = lerp(from.headingRadians, to.headingRadians, t);
      pose.pitchRadians = lerp(from.pitchRadians, to.pitchRadians, t);
      pose.rollRadians = lerp(from.rollRadians, to.rollRadians, t);
      auto below = (*ground)->terrainHeightMeters(pose.position.longitudeRadians,
                                                  pose.position.latitudeRadians);
      if (!below) return Error{below.error()};
      pose.position.heightMeters = std::max(pose.position.heightMeters, *below + clearanceMeters);
    }
    path.push_back(pose);
  }
  return path;
}

struct FlightStats {
  double medianMs = 0, p99Ms = 0, longestMs = 0;
  std::vector<double> frameMs;
  std::vector<size_t> arrivals;  // frames in which contents arrived
  double longestArrivalMs = 0;   // the longest of those
  double longestOtherMs = 0;     // the longest of the other frames
  size_t contentsAtEnd = 0;      // contents the last frame draws
  uint64_t trianglesAtEnd = 0;   // terrain + contents, the last frame
};

// The most these frames took over the median of their neighbours (the 4 frames before and the
// 4 after): what happened in them, the view's own cost at that point of the path set aside.
double largestExcessMs(const std::vector<double>& frameMs, const std::vector<size_t>& frames) {
  double largest = frames.empty() ? 0 : -1e300;
  const size_t n = frameMs.size();
  for (const size_t i : frames) {
    std::vector<double> neighbours;
    for (size_t j = i >= 4 ? i - 4 : 0; j <= std::min(n - 1, i + 4); ++j) {
      if (j != i) neighbours.push_back(frameMs[j]);
    }
    largest = std::max(largest, frameMs[i] - median(neighbours));
  }
  return largest;
}

// One flight on a fresh scene. `pngPrefix`: when set, the frames at a quarter, half, three
// quarters and the end are written as PNGs (after their time is taken).
Result<FlightStats> fly(const std::string& pyramid,
                        const std::shared_ptr<const tiles3d::Tileset>& tileset,
                        const std::vector<camera::CameraPose>& path, int width, int height,
                        const std::string& pngPrefix) {
  auto side = openSide(pyramid, tileset, true);
  if (!side) return Error{side.error()};
  std::vector<double> arrival, other;
  std::unordered_set<uint64_t> drawnBefore;
  FlightStats stats;
  const size_t n = path.size();
  for (size_t i = 0; i < n; ++i) {
    const double ms = timeFrame(*side, path[i], width, height);
    stats.frameMs.push_back(ms);
    std::unordered_set<uint64_t> drawn;
    size_t arrived = 0;
    for (const tiles3d::DrawnItem& item : side->scene->drawnModels()) {
      drawn.insert(item.id);
      if (!drawnBefore.contains(item.id)) ++arrived;
    }
    drawnBefore = std::move(drawn);
    (arrived ? arrival : other).push_back(ms);
    if (arrived) stats.arrivals.push_back(i);
    if (!pngPrefix.empty() && (i == n / 4 || i == n / 2 || i == 3 * n / 4 || i + 1 == n)) {
      const std::string file = pngPrefix + "-frame" + std::to_string(i) + ".png";
      if (auto written = writePng(file, width, height); !written) return Error{written.error()};
    }
  }
  stats.medianMs = median(stats.frameMs);
  stats.p99Ms = percentile(stats.frameMs, 0.99);
  stats.longestMs = maximum(stats.frameMs);
  stats.longestArrivalMs = maximum(arrival);
  stats.longestOtherMs = maximum(other);
  stats.contentsAtEnd = side->modelsDrawn;
  stats.trianglesAtEnd = side->terrainTriangles + side->modelTriangles;
  return stats;
}

std::string range(const std::vector<double>& values) {
  char text[64];
  std::snprintf(text, sizeof text, "%.1f–%.1f", *std::min_element(values.begin(), values.end()),
                *std::max_element(values.begin(), values.end()));
  return text;
}

int fail(const std::string& message) {
  std::fprintf(stderr, "globe-bench-tileset-frames: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{
      "Frame time with a 3D Tiles tileset against without it, steady and in a flight "
      "towards it (OSMesa)",
      "globe-bench-tileset-frames"};
  std::string pyramid, tilesetPath, out, sizeText = "1280x720", caseName = "tileset", label = "1",
                                         flightFrom, pngPrefix;
  std::vector<std::string> views;
  int rounds = 7, framesPerRound = 5, flightFrames = 200, flightRounds = 3;
  cli.add_option("--pyramid", pyramid, "terrain pyramid")->required();
  cli.add_option("--tileset", tilesetPath, "3D Tiles tileset.json or its folder")->required();
  cli.add_option("--view", views, "NAME=LON,LAT,HEIGHT,HEADING,PITCH,ROLL (repeatable)")
      ->required();
  cli.add_option("--flight-from", flightFrom,
                 "LON,LAT,HEIGHT,HEADING,PITCH,ROLL: a flight from here to the last --view");
  cli.add_option("--flight-frames", flightFrames, "frames a flight")->capture_default_str();
  cli.add_option("--flight-rounds", flightRounds, "flights a side, alternated")
      ->capture_default_str();
  cli.add_option("--size", sizeText, "WxH pixels")->capture_default_str();
  cli.add_option("--rounds", rounds, "interleaved rounds per view")->capture_default_str();
  cli.add_option("--frames", framesPerRound, "frames per side per round")->capture_default_str();
  cli.add_option("--case", caseName, "the case's name in the tables")->capture_default_str();
  cli.add_option("--label", label, "the run's name in the tables")->capture_default_str();
  cli.add_option("--png", pngPrefix,
                 "write each view with the tileset, and a flight's frames, as PREFIX-*.png "
                 "(an extra flight, not timed)");
  cli.add_option("--out", out, "also write the tables (Markdown rows) to this file");
  CLI11_PARSE(cli, argc, argv);

  auto size = app::parseSizeArgument(sizeText);
  if (!size) return fail(size.error());
  const auto [width, height] = *size;
  auto read = tiles3d::readTileset(tilesetPath);
  if (!read) return fail(read.error());
  const auto tileset = std::make_shared<const tiles3d::Tileset>(std::move(*read));
  std::vector<NamedPose> poses;
  for (const std::string& view : views) {
    auto pose = parseView(view);
    if (!pose) return fail(pose.error());
    poses.push_back(*pose);
  }
  auto context = render::OsMesaContext::create(width, height);
  if (!context) return fail(context.error());

  // | case | view | run | frames per side | without ms | with ms | ratio | terrain triangles
  // without | with: terrain + contents | contents drawn |
  std::string steadyRows;
  for (const NamedPose& view : poses) {
    auto without = openSide(pyramid, nullptr, false);
    auto with = without ? openSide(pyramid, tileset, false) : Result<Side>(Error{});
    if (!without || !with) {
      return fail(view.name + ": " + (!without ? without.error() : with.error()));
    }
    for (Side* side : {&*without, &*with}) {
      auto frame = side->scene->updateUntilComplete(view.pose, width, height, *side->gpu,
                                                    std::chrono::seconds(300));
      if (!frame) return fail(view.name + ": " + frame.error());
      timeFrame(*side, view.pose, width, height);  // the contents uploaded
    }
    if (!pngPrefix.empty()) {
      for (auto [side, name] : {std::pair{&*without, "without"}, std::pair{&*with, "with"}}) {
        timeFrame(*side, view.pose, width, height);
        const std::string file = pngPrefix + "-" + view.name + "-" + name + ".png";
        if (auto written = writePng(file, width, height); !written) return fail(written.error());
      }
    }
    for (int round = 0; round < rounds; ++round) {
      for (Side* side : {&*without, &*with}) {
        for (int f = 0; f < framesPerRound; ++f) {
          side->frameMs.push_back(timeFrame(*side, view.pose, width, height));
        }
      }
    }
    const double a = median(without->frameMs), b = median(with->frameMs);
    char row[512];
    std::snprintf(row, sizeof row,
                  "| %s | %s | %s | %zu | %.1f | %.1f | %.2f | %llu | %llu + %llu | %zu |\n",
                  caseName.c_str(), view.name.c_str(), label.c_str(), with->frameMs.size(), a, b,
                  b / a, static_cast<unsigned long long>(without->terrainTriangles),
                  static_cast<unsigned long long>(with->terrainTriangles),
                  static_cast<unsigned long long>(with->modelTriangles), with->modelsDrawn);
    steadyRows += row;
    std::fputs(row, stdout);
    std::fflush(stdout);
  }

  std::string flightRows;
  if (!flightFrom.empty()) {
    auto from = app::parseCameraArgument(flightFrom);
    if (!from) return fail("--flight-from: " + from.error());
    auto path = flightPath(pyramid, *from, poses.back().pose, flightFrames, 60.0);
    if (!path) return fail(path.error());
    if (!pngPrefix.empty()) {
      auto shown = fly(pyramid, tileset, *path, width, height, pngPrefix + "-flight");
      if (!shown) return fail(shown.error());
    }
    std::vector<FlightStats> sides[2];  // without, with
    for (int round = 0; round < flightRounds; ++round) {
      for (int k = 0; k < 2; ++k) {
        const int s = (round % 2 == 0) ? k : 1 - k;  // alternate which side flies first
        auto stats = fly(pyramid, s == 1 ? tileset : nullptr, *path, width, height, "");
        if (!stats) return fail(stats.error());
        sides[s].push_back(*stats);
      }
    }
    auto each = [](const std::vector<FlightStats>& flights, double FlightStats::*field) {
      std::vector<double> values;
      for (const FlightStats& f : flights) values.push_back(f.*field);
      return values;
    };
    const std::vector<double> longest0 = each(sides[0], &FlightStats::longestMs),
                              longest1 = each(sides[1], &FlightStats::longestMs);
    const double m0 = median(each(sides[0], &FlightStats::medianMs)),
                 m1 = median(each(sides[1], &FlightStats::medianMs));
    const double p0 = median(each(sides[0], &FlightStats::p99Ms)),
                 p1 = median(each(sides[1], &FlightStats::p99Ms));
    const double l0 = median(longest0), l1 = median(longest1);
    // The arrival frames' excess over their neighbours with the tileset, and the same frames
    // (the same poses) of the flight without it beside it: the noise of a frame there.
    std::vector<double> excessWith, excessWithout;
    for (int round = 0; round < flightRounds; ++round) {
      const std::vector<size_t>& arrivals = sides[1][round].arrivals;
      excessWith.push_back(largestExcessMs(sides[1][round].frameMs, arrivals));
      excessWithout.push_back(largestExcessMs(sides[0][round].frameMs, arrivals));
    }
    std::string arrivalFrames;
    for (const size_t i : sides[1].front().arrivals) {
      arrivalFrames += (arrivalFrames.empty() ? "" : ", ") + std::to_string(i);
    }
    // | case | run | flights a side × frames | median ms without, with | p99 ms without, with |
    // longest ms without, with (flights' range) | ratio of the longest | the frames contents
    // arrived in (the first flight) | the longest of those ms | the most one took over its
    // neighbours with, the same frames without ms | the longest of the other frames ms |
    // contents, triangles at the end |
    char row[1024];
    std::snprintf(row, sizeof row,
                  "| %s | %s | %d × %d | %.1f, %.1f | %.1f, %.1f | %.1f (%s), %.1f (%s) | %.2f | "
                  "%s | %.1f | %+.1f, %+.1f | %.1f | %zu, %llu |\n",
                  caseName.c_str(), label.c_str(), flightRounds, flightFrames, m0, m1, p0, p1, l0,
                  range(longest0).c_str(), l1, range(longest1).c_str(), l1 / l0,
                  arrivalFrames.c_str(), median(each(sides[1], &FlightStats::longestArrivalMs)),
                  median(excessWith), median(excessWithout),
                  median(each(sides[1], &FlightStats::longestOtherMs)),
                  sides[1].front().contentsAtEnd,
                  static_cast<unsigned long long>(sides[1].front().trianglesAtEnd));
    flightRows += row;
    std::fputs(row, stdout);
    std::fflush(stdout);
  }
  if (!out.empty()) {
    if (auto written =
            transport::writeFileAtomically(out, "STEADY\n" + steadyRows + "FLIGHT\n" + flightRows);
        !written) {
      return fail(written.error());
    }
  }
  return 0;
}
