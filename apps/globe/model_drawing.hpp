// The scene's 3D Tiles tilesets drawn over its terrain (render/model_renderer.hpp): their
// contents at the finest levels, uploaded once.
#pragma once

#include <memory>

#include "core/result.hpp"
#include "render/model_renderer.hpp"
#include "scene/terrain_scene.hpp"

namespace globe::app {

class ModelDrawing {
 public:
  // Needs the GL context current; nullptr when the scene has no tilesets.
  static Result<std::unique_ptr<ModelDrawing>> create(const scene::TerrainScene& scene);
  // After the terrain, with the scene's last view.
  void draw(const scene::TerrainScene& scene) { renderer_->draw(scene.view()); }
  size_t triangleCount() const { return renderer_->triangleCount(); }

 private:
  explicit ModelDrawing(std::unique_ptr<render::ModelRenderer> renderer)
      : renderer_(std::move(renderer)) {}
  std::unique_ptr<render::ModelRenderer> renderer_;
};

}  // namespace globe::app
