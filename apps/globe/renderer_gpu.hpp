// The scene's TileGpu over the GL terrain renderer, and drawing a scene's frame with it.
#pragma once

#include <array>
#include <vector>

#include "render/frame_stats.hpp"
#include "render/terrain_renderer.hpp"
#include "scene/terrain_scene.hpp"
#include "scene/tile_gpu.hpp"

namespace globe::app {

class RendererGpu final : public scene::TileGpu {
 public:
  // Sets the renderer's sky and imagery lighting from the scene's options.
  RendererGpu(render::TerrainRenderer& renderer, const scene::SceneOptions& options);

  bool hasTile(const geo::TileId& tile) const override { return renderer_.hasTile(tile); }
  Result<void> prepareTile(const geo::TileId& tile, const terrain::TileMesh& mesh) override {
    return renderer_.uploadTile(tile, mesh);
  }
  bool releaseTile(const geo::TileId& tile) override { return renderer_.evictTile(tile); }
  Result<void> prepareTileSunlight(const geo::TileId& tile,
                                   std::span<const float> gridVisibility) override {
    return renderer_.setTileSunlight(tile, gridVisibility);
  }

  bool hasImageryTile(uint32_t layer, const geo::TileId& tile) const override {
    return renderer_.hasImageryTile(layer, tile);
  }
  Result<void> prepareImageryTile(uint32_t layer, const geo::TileId& tile,
                                  std::span<const uint8_t> rgba, int widthPixels,
                                  int heightPixels) override {
    return renderer_.uploadImageryTile(layer, tile, rgba, widthPixels, heightPixels);
  }
  bool releaseImageryTile(uint32_t layer, const geo::TileId& tile) override {
    return renderer_.evictImageryTile(layer, tile);
  }
  uint64_t imageryBytesResident() const override { return renderer_.imageryBytesResident(); }

  render::TerrainRenderer& renderer() { return renderer_; }
  // Draws the scene's last update: its view, tiles and (with layers) drapes, the layers as
  // setLayer says.
  render::FrameStats draw(const scene::TerrainScene& scene);

  // The window's controls: how the imagery is lit, and each layer (index as in --layer) shown
  // or not at this opacity (0..1) instead of the scene's. A hidden layer is still loaded.
  void setImageryLighting(terrain::ImageryLighting lighting);
  void setLayer(uint32_t layer, bool shown, float opacity);

 private:
  struct LayerOverride {
    bool set = false;
    bool shown = true;
    float opacity = 1.0f;
    float sceneOpacity = 1.0f;  // --layer's
  };
  render::TerrainRenderer& renderer_;
  std::array<LayerOverride, terrain::kMaxDrapeLayers> layers_{};
  std::vector<terrain::TileDrapes> drapes_;  // the scene's, overridden (reused each frame)
};

}  // namespace globe::app
