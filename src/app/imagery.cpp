#include "app/imagery.hpp"

#include "io/image_io.hpp"

namespace globe::app {

Result<void> drapeImagery(render::TerrainRenderer& renderer, const std::filesystem::path& path) {
  auto image = io::loadImageRgba(path);
  if (!image) return Error{image.error()};
  return renderer.setImagery(image->pixels, image->widthPixels, image->heightPixels);
}

}  // namespace globe::app
