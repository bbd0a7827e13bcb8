#include "apps/globe/model_drawing.hpp"

namespace globe::app {

Result<std::unique_ptr<ModelDrawing>> ModelDrawing::create(const scene::TerrainScene& scene) {
  if (scene.options().tilesets.empty()) return std::unique_ptr<ModelDrawing>();
  auto renderer = render::ModelRenderer::create({});
  if (!renderer) return Error{renderer.error()};
  for (const auto& tileset : scene.options().tilesets) {
    for (const tiles3d::DrawnContent* content : tileset->drawnContents()) {
      render::ModelMesh mesh;
      mesh.originEcefMeters = content->originEcefMeters;
      mesh.offsetsMeters = content->offsetsMeters;
      (*renderer)->add(mesh);
    }
  }
  return std::unique_ptr<ModelDrawing>(new ModelDrawing(std::move(*renderer)));
}

}  // namespace globe::app
