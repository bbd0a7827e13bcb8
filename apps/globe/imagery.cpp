#include "apps/globe/imagery.hpp"

#include "formats/image_io.hpp"

namespace globe::app {

Result<void> drapeImagery(render::TerrainRenderer& renderer, const std::filesystem::path& path) {
  auto image = formats::loadImageRgba(path);
  if (!image) return Error{image.error()};
  return renderer.setImagery(image->pixels, image->widthPixels, image->heightPixels);
}

}  // namespace globe::app
