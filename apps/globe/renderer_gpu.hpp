// The scene's TileGpu over the GL terrain renderer, and drawing a scene's frame with it.
#pragma once

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
  // Draws the scene's last update: its view, tiles and (with layers) drapes.
  render::FrameStats draw(const scene::TerrainScene& scene);

 private:
  render::TerrainRenderer& renderer_;
};

}  // namespace globe::app
