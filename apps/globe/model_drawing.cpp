#include "apps/globe/model_drawing.hpp"

#include <vector>

namespace globe::app {

Result<std::unique_ptr<ModelDrawing>> ModelDrawing::create(const scene::TerrainScene& scene) {
  if (scene.options().tilesets.empty()) return std::unique_ptr<ModelDrawing>();
  auto renderer = render::ModelRenderer::create({});
  if (!renderer) return Error{renderer.error()};
  return std::unique_ptr<ModelDrawing>(new ModelDrawing(std::move(*renderer)));
}

void ModelDrawing::draw(const scene::TerrainScene& scene) {
  for (auto it = uploaded_.begin(); it != uploaded_.end();) {
    if (it->second.expired()) {
      renderer_->remove(it->first);
      it = uploaded_.erase(it);
    } else {
      ++it;
    }
  }
  std::vector<uint64_t> ids;
  ids.reserve(scene.drawnModels().size());
  for (const tiles3d::DrawnItem& item : scene.drawnModels()) {
    ids.push_back(item.id);
    if (uploaded_.contains(item.id)) continue;
    render::ModelMesh mesh;
    mesh.originEcefMeters = item.content->drawn.originEcefMeters;
    for (const tiles3d::DrawnPart& drawn : item.content->drawn.parts) {
      render::ModelPart part{drawn.offsetsMeters, drawn.normals, drawn.uvs, drawn.surface.baseColor,
                             drawn.surface.alphaCutoff};
      if (const auto& texture = drawn.surface.texture) {
        part.texturePixels = texture->rgba.data();
        part.textureWidth = texture->widthPixels;
        part.textureHeight = texture->heightPixels;
      }
      mesh.parts.push_back(std::move(part));
    }
    renderer_->add(item.id, mesh);
    uploaded_.emplace(item.id, item.content);
  }
  renderer_->draw(scene.view(), ids);
}

}  // namespace globe::app
