#include "render_scenarios.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <sstream>
#include <string>

#include "apps/globe/renderer_gpu.hpp"
#include "apps/globe/stderr_warnings.hpp"
#include "apps/globe/view_command.hpp"
#include "render/osmesa_context.hpp"
#include "render/read_pixels.hpp"

namespace globe::bench {
namespace {

using Clock = std::chrono::steady_clock;

// CPU time of the whole process: all llvmpipe threads included.
double processCpuMilliseconds() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) / 1e6;
}

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Nearest-rank percentile; 0 for no samples.
double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<size_t>(std::ceil(p / 100 * static_cast<double>(values.size())));
  return values[std::clamp<size_t>(rank, 1, values.size()) - 1];
}

struct Context {
  scene::TerrainScene& scene;
  app::RendererGpu& gpu;
  const ScenarioOptions& options;
};

void fillStats(ScenarioRow& row, const render::FrameStats& stats) {
  row.tilesDrawn = stats.tilesDrawn;
  row.drawCalls = stats.drawCalls;
  row.triangles = stats.triangles;
  row.gpuBytes = stats.gpuBytesResident;
}

// `frames` frames of a view that is already complete: update + draw + glFinish each.
ScenarioRow steadyFrames(Context& c, const std::string& name, const camera::CameraPose& pose) {
  ScenarioRow row;
  row.name = name;
  row.frames = c.options.frames;
  std::vector<double> total, draw, update, cpu;
  render::FrameStats stats;
  for (int k = 0; k < c.options.frames; ++k) {
    const double cpuStart = processCpuMilliseconds();
    const auto start = Clock::now();
    c.scene.update(pose, c.options.widthPixels, c.options.heightPixels, c.gpu);
    const auto updated = Clock::now();
    stats = c.gpu.draw(c.scene);
    render::finishGl();
    total.push_back(millisecondsSince(start));
    draw.push_back(millisecondsSince(updated));
    update.push_back(std::chrono::duration<double, std::milli>(updated - start).count());
    cpu.push_back(processCpuMilliseconds() - cpuStart);
  }
  row.medianCpuMs = percentile(cpu, 50);
  row.medianMs = percentile(total, 50);
  row.p90Ms = percentile(total, 90);
  row.minMs = percentile(total, 0);
  row.medianDrawMs = percentile(draw, 50);
  row.medianUpdateMs = percentile(update, 50);
  fillStats(row, stats);
  return row;
}

// The last update's tiles and matrices drawn into a viewport 1/8 as wide and high: the same
// vertices and triangles, 1/64 of the fragments; what remains is vertex and setup work (and the
// full-size clear).
ScenarioRow smallViewportFrames(Context& c, const std::string& name) {
  ScenarioRow row;
  row.name = name;
  row.frames = c.options.frames;
  terrain::RenderView view = c.scene.view();
  view.widthPixels = std::max(view.widthPixels / 8, 1);
  view.heightPixels = std::max(view.heightPixels / 8, 1);
  std::vector<double> draw, cpu;
  render::FrameStats stats;
  for (int k = 0; k < c.options.frames; ++k) {
    const double cpuStart = processCpuMilliseconds();
    const auto start = Clock::now();
    stats = c.gpu.renderer().draw(view, c.scene.tiles());
    render::finishGl();
    draw.push_back(millisecondsSince(start));
    cpu.push_back(processCpuMilliseconds() - cpuStart);
  }
  row.medianCpuMs = percentile(cpu, 50);
  row.medianMs = row.medianDrawMs = percentile(draw, 50);
  row.p90Ms = percentile(draw, 90);
  row.minMs = percentile(draw, 0);
  fillStats(row, stats);
  return row;
}

// Renders frames back to back (no waiting) from a new pose until the view is complete.
Result<ScenarioRow> framesUntilComplete(Context& c, const std::string& name,
                                        const camera::CameraPose& pose) {
  ScenarioRow row;
  row.name = name;
  const uint64_t loadsBefore = c.scene.loader().counters().completed;
  const auto start = Clock::now();
  for (;;) {
    const scene::FrameInfo info =
        c.scene.update(pose, c.options.widthPixels, c.options.heightPixels, c.gpu);
    fillStats(row, c.gpu.draw(c.scene));
    render::finishGl();
    ++row.frames;
    if (info.complete) break;
    if (millisecondsSince(start) > 300e3) return makeError(name + ": not complete after 300 s");
  }
  row.wallMs = millisecondsSince(start);
  row.tileLoads = c.scene.loader().counters().completed - loadsBefore;
  return row;
}

// The same jump paced as `globe view` paces it: update as soon as a load finishes, draw at most
// every kLoadingRedrawInterval until the view is complete, then once more.
Result<ScenarioRow> viewerPacedUntilComplete(Context& c, const std::string& name,
                                             const camera::CameraPose& pose) {
  ScenarioRow row;
  row.name = name;
  const uint64_t loadsBefore = c.scene.loader().counters().completed;
  const auto start = Clock::now();
  auto lastDraw = start - app::kLoadingRedrawInterval;
  for (;;) {
    const scene::FrameInfo info =
        c.scene.update(pose, c.options.widthPixels, c.options.heightPixels, c.gpu);
    if (info.complete || Clock::now() - lastDraw >= app::kLoadingRedrawInterval) {
      lastDraw = Clock::now();
      fillStats(row, c.gpu.draw(c.scene));
      render::finishGl();
      ++row.frames;
    }
    if (info.complete) break;
    if (millisecondsSince(start) > 300e3) return makeError(name + ": not complete after 300 s");
    c.scene.waitForLoads(app::kLoadWait);
  }
  row.wallMs = millisecondsSince(start);
  row.tileLoads = c.scene.loader().counters().completed - loadsBefore;
  return row;
}

}  // namespace

Result<std::vector<ScenarioRow>> runScenarios(const ScenarioOptions& options,
                                              std::string& rendererName) {
  scene::SceneOptions sceneOptions;
  sceneOptions.maximumScreenSpaceErrorPixels = options.maximumScreenSpaceErrorPixels;
  sceneOptions.warnings = app::stderrWarnings();
  sceneOptions.network =
      std::make_shared<transport::Network>(transport::NetworkSettings{}, sceneOptions.warnings);
  auto scene = scene::TerrainScene::open(options.pyramid, sceneOptions);
  if (!scene) return Error{scene.error()};
  auto context = render::OsMesaContext::create(options.widthPixels, options.heightPixels);
  if (!context) return Error{context.error()};
  render::TerrainRendererOptions rendererOptions;
  rendererOptions.shaderDirectory = options.shaderDirectory;
  auto renderer = render::TerrainRenderer::create(rendererOptions);
  if (!renderer) return Error{renderer.error()};
  rendererName = reinterpret_cast<const char*>(glGetString(GL_RENDERER));

  const auto globe = camera::CameraPose::fromDegrees(138, 30, 20e6);
  const auto fuji = camera::CameraPose::fromDegrees(138.60, 35.20, 3000, 30, -12, 0);
  app::RendererGpu gpu(**renderer, sceneOptions);
  Context c{**scene, gpu, options};
  std::vector<ScenarioRow> rows;
  auto cold = framesUntilComplete(c, "cold start -> whole globe complete", globe);
  if (!cold) return Error{cold.error()};
  rows.push_back(*cold);
  rows.push_back(steadyFrames(c, "(b) whole globe 138,30,2e7 m", globe));
  rows.back().tileLoads = cold->tileLoads;
  auto jump = framesUntilComplete(c, "(c) jump globe -> Fuji oblique", fuji);
  if (!jump) return Error{jump.error()};
  rows.push_back(*jump);
  rows.push_back(steadyFrames(c, "(a) Fuji oblique 138.60,35.20,3000 m,30,-12", fuji));
  rows.back().tileLoads = jump->tileLoads;
  rows.push_back(smallViewportFrames(c, "(a) same tiles, viewport 1/8 wide and high"));

  // The jump again from a cold cache, paced as the interactive viewer paces it.
  (*renderer)->evictAllTiles();
  auto fresh = scene::TerrainScene::open(options.pyramid, sceneOptions);
  if (!fresh) return Error{fresh.error()};
  Context again{**fresh, gpu, options};
  if (auto globeAgain = framesUntilComplete(again, "globe", globe); !globeAgain) {
    return Error{globeAgain.error()};
  }
  auto paced = viewerPacedUntilComplete(again, "(c') the same jump paced as globe view", fuji);
  if (!paced) return Error{paced.error()};
  rows.push_back(*paced);
  return rows;
}

std::string formatRow(const ScenarioRow& r) {
  std::ostringstream out;
  out << r.name << '\t' << r.frames << '\t' << r.medianMs << '\t' << r.p90Ms << '\t' << r.minMs
      << '\t' << r.medianDrawMs << '\t' << r.medianUpdateMs << '\t' << r.wallMs << '\t'
      << r.medianCpuMs << '\t' << r.tilesDrawn << '\t' << r.drawCalls << '\t' << r.triangles << '\t'
      << r.tileLoads << '\t' << r.gpuBytes;
  return out.str();
}

bool parseRow(const std::string& line, ScenarioRow& r) {
  std::istringstream in(line);
  if (!std::getline(in, r.name, '\t')) return false;
  in >> r.frames >> r.medianMs >> r.p90Ms >> r.minMs >> r.medianDrawMs >> r.medianUpdateMs >>
      r.wallMs >> r.medianCpuMs >> r.tilesDrawn >> r.drawCalls >> r.triangles >> r.tileLoads >>
      r.gpuBytes;
  return !in.fail();
}

}  // namespace globe::bench
