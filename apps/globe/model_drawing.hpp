// The scene's 3D Tiles contents drawn over its terrain (render/model_renderer.hpp): each frame,
// the contents the scene draws (TerrainScene::drawnModels) uploaded as they first appear and
// released once the scene has dropped them.
#pragma once

#include <memory>
#include <unordered_map>

#include "core/result.hpp"
#include "render/model_renderer.hpp"
#include "scene/terrain_scene.hpp"

namespace globe::app {

class ModelDrawing {
 public:
  // Needs the GL context current; nullptr when the scene has no tilesets.
  static Result<std::unique_ptr<ModelDrawing>> create(const scene::TerrainScene& scene);
  // After the terrain, with the scene's last view and contents.
  void draw(const scene::TerrainScene& scene);
  size_t trianglesDrawn() const { return renderer_->trianglesDrawn(); }

 private:
  explicit ModelDrawing(std::unique_ptr<render::ModelRenderer> renderer)
      : renderer_(std::move(renderer)) {}
  std::unique_ptr<render::ModelRenderer> renderer_;
  // What is uploaded, watched: a content the scene no longer holds is released.
  std::unordered_map<uint64_t, std::weak_ptr<const tiles3d::LoadedContent>> uploaded_;
};

}  // namespace globe::app
