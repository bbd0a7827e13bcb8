#include "apps/globe/renderer_gpu.hpp"

namespace globe::app {

RendererGpu::RendererGpu(render::TerrainRenderer& renderer, const scene::SceneOptions& options)
    : renderer_(renderer) {
  render::TerrainStyle style = renderer_.style();
  style.sky = options.sky;
  if (!options.layers.empty()) style.lightImagery = options.lightImagery;
  renderer_.setStyle(style);
}

render::FrameStats RendererGpu::draw(const scene::TerrainScene& scene) {
  if (scene.imagery() != nullptr)
    return renderer_.draw(scene.view(), scene.tiles(), scene.drapes());
  return renderer_.draw(scene.view(), scene.tiles());
}

}  // namespace globe::app
