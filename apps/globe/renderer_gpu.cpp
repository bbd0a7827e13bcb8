#include "apps/globe/renderer_gpu.hpp"

#include <algorithm>

namespace globe::app {

RendererGpu::RendererGpu(render::TerrainRenderer& renderer, const scene::SceneOptions& options)
    : renderer_(renderer) {
  render::TerrainStyle style = renderer_.style();
  style.sky = options.sky;
  if (!options.layers.empty()) style.imageryLighting = options.imageryLighting;
  for (size_t k = 0; k < std::min(options.layers.size(), layers_.size()); ++k)
    layers_[k].sceneOpacity = options.layers[k].opacity;
  renderer_.setStyle(style);
}

render::FrameStats RendererGpu::draw(const scene::TerrainScene& scene) {
  if (scene.imagery() == nullptr) return renderer_.draw(scene.view(), scene.tiles());
  const bool overridden = std::any_of(layers_.begin(), layers_.end(),
                                      [](const LayerOverride& layer) { return layer.set; });
  if (!overridden) return renderer_.draw(scene.view(), scene.tiles(), scene.drapes());
  // Hidden layers are dropped rather than drawn at opacity 0: no texture fetch for them.
  const auto drapes = scene.drapes();
  drapes_.assign(drapes.begin(), drapes.end());
  for (terrain::TileDrapes& tile : drapes_) {
    uint32_t kept = 0;
    for (uint32_t k = 0; k < std::min(tile.count, terrain::kMaxDrapeLayers); ++k) {
      terrain::TileDrape drape = tile.layers[k];
      if (drape.layer < layers_.size() && layers_[drape.layer].set) {
        if (!layers_[drape.layer].shown) continue;
        drape.opacity = layers_[drape.layer].opacity;
      }
      tile.layers[kept++] = drape;
    }
    tile.count = kept;
  }
  return renderer_.draw(scene.view(), scene.tiles(), drapes_);
}

void RendererGpu::setImageryLighting(terrain::ImageryLighting lighting) {
  render::TerrainStyle style = renderer_.style();
  style.imageryLighting = lighting;
  renderer_.setStyle(style);
}

void RendererGpu::setLayer(uint32_t layer, bool shown, float opacity) {
  if (layer >= layers_.size()) return;
  LayerOverride& entry = layers_[layer];
  entry.set = !shown || opacity != entry.sceneOpacity;  // as the scene draws it: no copy
  entry.shown = shown;
  entry.opacity = opacity;
}

}  // namespace globe::app
