// globe-bench-drape: the frame time of steady views with imagery layers against the same views
// without, in one process and one GL context (OSMesa), rounds interleaved so that every side sees
// the same machine load. Four sides: without imagery as the viewer draws it, the imagery side's
// scene drawn without its imagery (under a layer the terrain may refine further: the layer's
// imagery follows the terrain's level, scene/imagery_layers.hpp), with imagery, and with imagery
// sampled trilinearly everywhere (TerrainStyle::bilinearWhereMagnified off: the renderer before
// it, the baseline of that change). The first ratio is what a user sees when turning imagery on;
// the second the imagery's own cost on the same geometry. A table printer, not a timed test.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "apps/globe/camera_argument.hpp"
#include "apps/globe/layer_argument.hpp"
#include "apps/globe/renderer_gpu.hpp"
#include "apps/globe/stderr_warnings.hpp"
#include "render/osmesa_context.hpp"
#include "render/read_pixels.hpp"
#include "scene/terrain_scene.hpp"
#include "transport/atomic_file.hpp"

namespace {

using namespace globe;
using Clock = std::chrono::steady_clock;

struct Side {
  std::unique_ptr<render::TerrainRenderer> renderer;
  std::unique_ptr<app::RendererGpu> gpu;  // over renderer
  std::unique_ptr<scene::TerrainScene> scene;
  std::vector<double> frameMs;
  uint64_t triangles = 0, imageryBytes = 0;
  size_t drapes = 0;
  uint32_t drapesMagnified = 0;  // drawn with the bilinear sampler
  bool drawDrapes = true;        // false: the scene's tiles without their imagery
};

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::nth_element(values.begin(), values.begin() + static_cast<long>(values.size() / 2),
                   values.end());
  return values[values.size() / 2];
}

Result<Side> openSide(const std::string& pyramid, const std::vector<scene::LayerOptions>& layers,
                      const camera::CameraPose& pose, int width, int height) {
  Side side;
  scene::SceneOptions options;
  options.warnings = app::stderrWarnings();
  render::TerrainRendererOptions rendererOptions;
  rendererOptions.warn = options.warnings;
  auto renderer = render::TerrainRenderer::create(rendererOptions);
  if (!renderer) return Error{renderer.error()};
  side.renderer = std::move(*renderer);
  options.hysteresis = false;
  options.layers = layers;
  auto scene = scene::TerrainScene::open(pyramid, options);
  if (!scene) return Error{scene.error()};
  side.scene = std::move(*scene);
  side.gpu = std::make_unique<app::RendererGpu>(*side.renderer, options);
  auto frame =
      side.scene->updateUntilComplete(pose, width, height, *side.gpu, std::chrono::seconds(300));
  if (!frame) return Error{frame.error()};
  side.drapes = frame->imagery.drapes;
  return side;
}

// One steady frame as the viewer runs it: update (selection, polls), draw, glFinish.
double timeFrame(Side& side, const camera::CameraPose& pose, int width, int height) {
  const auto start = Clock::now();
  side.scene->update(pose, width, height, *side.gpu);
  const render::FrameStats stats =
      side.drawDrapes ? side.gpu->draw(*side.scene)
                      : side.renderer->draw(side.scene->view(), side.scene->tiles());
  render::finishGl();
  side.triangles = stats.triangles;
  side.drapesMagnified = stats.drapesMagnified;
  side.imageryBytes = stats.imageryBytesResident;
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"Frame time of steady views with imagery layers against without (OSMesa)",
               "globe-bench-drape"};
  std::string pyramid, out, sizeText = "1280x720";
  std::vector<std::string> layerTexts, views;
  int rounds = 7, framesPerRound = 5;
  cli.add_option("--pyramid", pyramid, "terrain pyramid")->required();
  cli.add_option("--layer", layerTexts, "imagery layer DIR[,OPACITY], bottom first")->required();
  cli.add_option("--view", views, "NAME=LON,LAT,HEIGHT,HEADING,PITCH,ROLL (repeatable)")
      ->required();
  cli.add_option("--size", sizeText, "WxH pixels")->capture_default_str();
  cli.add_option("--rounds", rounds, "interleaved rounds per view")->capture_default_str();
  cli.add_option("--frames", framesPerRound, "frames per side per round")->capture_default_str();
  cli.add_option("--out", out, "also write the table (Markdown) to this file");
  CLI11_PARSE(cli, argc, argv);

  auto size = app::parseSizeArgument(sizeText);
  if (!size) {
    std::fprintf(stderr, "globe-bench-drape: %s\n", size.error().c_str());
    return 2;
  }
  const auto [width, height] = *size;
  std::vector<scene::LayerOptions> layers;
  for (const std::string& text : layerTexts) {
    auto layer = app::parseLayerArgument(text);
    if (!layer) {
      std::fprintf(stderr, "globe-bench-drape: %s\n", layer.error().c_str());
      return 2;
    }
    layers.push_back(*layer);
  }
  auto context = render::OsMesaContext::create(width, height);
  if (!context) {
    std::fprintf(stderr, "globe-bench-drape: %s\n", context.error().c_str());
    return 1;
  }

  std::string table =
      "| view | frames per side | without: median ms | without, the imagery side's tiles: "
      "median ms | with imagery: median ms | ratio as the viewer runs | ratio, same tiles | "
      "triangles without | triangles with | drapes | of them magnified (bilinear) | imagery "
      "textures MiB | with imagery, trilinear everywhere: median ms | its ratio as the viewer "
      "runs |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string& view : views) {
    const size_t equals = view.find('=');
    if (equals == std::string::npos) {
      std::fprintf(stderr, "globe-bench-drape: --view %s: expected NAME=CAMERA\n", view.c_str());
      return 2;
    }
    const std::string name = view.substr(0, equals);
    auto pose = app::parseCameraArgument(view.substr(equals + 1));
    if (!pose) {
      std::fprintf(stderr, "globe-bench-drape: --view %s: %s\n", view.c_str(),
                   pose.error().c_str());
      return 2;
    }
    auto without = openSide(pyramid, {}, *pose, width, height);
    // The imagery side's scene (its tiles, its loads), drawn without the imagery.
    auto sameTiles =
        without ? openSide(pyramid, layers, *pose, width, height) : Result<Side>(Error{});
    if (sameTiles) sameTiles->drawDrapes = false;
    auto with = sameTiles ? openSide(pyramid, layers, *pose, width, height) : Result<Side>(Error{});
    auto trilinear = with ? openSide(pyramid, layers, *pose, width, height) : Result<Side>(Error{});
    if (!without || !sameTiles || !with || !trilinear) {
      const std::string& error =
          !without ? without.error()
                   : (!sameTiles ? sameTiles.error() : (!with ? with.error() : trilinear.error()));
      std::fprintf(stderr, "globe-bench-drape: %s: %s\n", name.c_str(), error.c_str());
      return 1;
    }
    render::TerrainStyle style = trilinear->renderer->style();
    style.bilinearWhereMagnified = false;
    trilinear->renderer->setStyle(style);
    for (int round = 0; round < rounds; ++round) {
      for (Side* side : {&*without, &*sameTiles, &*with, &*trilinear}) {
        for (int f = 0; f < framesPerRound; ++f) {
          side->frameMs.push_back(timeFrame(*side, *pose, width, height));
        }
      }
    }
    const double a = median(without->frameMs), n = median(sameTiles->frameMs),
                 b = median(with->frameMs), t = median(trilinear->frameMs);
    char row[512];
    std::snprintf(
        row, sizeof row,
        "| %s | %zu | %.1f | %.1f | %.1f | %.2f | %.2f | %llu | %llu | %zu | %u | %.1f | %.1f | "
        "%.2f |\n",
        name.c_str(), with->frameMs.size(), a, n, b, b / a, b / n,
        static_cast<unsigned long long>(without->triangles),
        static_cast<unsigned long long>(with->triangles), with->drapes, with->drapesMagnified,
        static_cast<double>(with->imageryBytes) / (1 << 20), t, t / a);
    table += row;
    std::fputs(row, stdout);
    std::fflush(stdout);
  }
  if (!out.empty()) {
    if (auto written = transport::writeFileAtomically(out, table); !written) {
      std::fprintf(stderr, "globe-bench-drape: %s\n", written.error().c_str());
      return 1;
    }
  }
  return 0;
}
