// ImageOverlay: one texture, a four-vertex strip made in the vertex shader (shaders/image.*).
#include "render/image_overlay.hpp"

#include "render/gl.hpp"
#include "render/gl_object.hpp"
#include "render/pixel_unpack.hpp"
#include "render/shader_directory.hpp"
#include "render/shader_program.hpp"

namespace globe::render {

struct ImageOverlay::Impl {
  ShaderProgram program;
  GLint rectLocation = -1, viewportLocation = -1, opacityLocation = -1, textureLocation = -1;
  GlObject vertexArray;  // core profile draws need one bound, though it holds nothing
  GlObject texture;
  glm::ivec2 size{0, 0};
};

ImageOverlay::ImageOverlay(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ImageOverlay::~ImageOverlay() = default;

Result<std::unique_ptr<ImageOverlay>> ImageOverlay::create(
    const std::filesystem::path& shaderDirectory) {
  const std::filesystem::path dir =
      shaderDirectory.empty() ? defaultShaderDirectory() : shaderDirectory;
  auto program = loadNamedShaderProgram(dir, "image.vert", "image.frag");
  if (!program) return makeError(program.error());
  auto impl = std::make_unique<Impl>();
  impl->program = std::move(*program);
  impl->rectLocation = impl->program.uniformLocation("u_rectPixels");
  impl->viewportLocation = impl->program.uniformLocation("u_viewportPixels");
  impl->opacityLocation = impl->program.uniformLocation("u_opacity");
  impl->textureLocation = impl->program.uniformLocation("u_texture");
  if (impl->rectLocation < 0 || impl->viewportLocation < 0) {
    return makeError((dir / "image.vert").string() +
                     ": the program lacks u_rectPixels or u_viewportPixels");
  }
  impl->vertexArray = makeGlVertexArray();
  return std::unique_ptr<ImageOverlay>(new ImageOverlay(std::move(impl)));
}

void ImageOverlay::setImage(const formats::ImageRgba& image) {
  const glm::ivec2 size(image.widthPixels, image.heightPixels);
  if (size.x <= 0 || size.y <= 0 || size.x > formats::kMaxDecodedImageSide ||
      size.y > formats::kMaxDecodedImageSide ||
      image.pixels.size() != static_cast<size_t>(4 * size.x * size.y)) {
    impl_->texture = GlObject();
    impl_->size = {0, 0};
    return;
  }
  if (!impl_->texture.get()) impl_->texture = makeGlTexture();
  glBindTexture(GL_TEXTURE_2D, impl_->texture.get());
  {
    const TightUnpack tight;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.x, size.y, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 image.pixels.data());
  }
  // Drawn texel for pixel: nearest keeps text sharp.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  impl_->size = size;
}

bool ImageOverlay::hasImage() const { return impl_->size.x > 0; }
glm::ivec2 ImageOverlay::sizePixels() const { return impl_->size; }

void ImageOverlay::draw(glm::vec2 topLeftPixels, int widthPixels, int heightPixels,
                        float opacity) const {
  if (!hasImage() || widthPixels <= 0 || heightPixels <= 0) return;
  glViewport(0, 0, widthPixels, heightPixels);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  // Colour blends; the framebuffer's alpha stays opaque (screenshots keep no holes).
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  glUseProgram(impl_->program.id());
  glUniform4f(impl_->rectLocation, topLeftPixels.x, topLeftPixels.y,
              static_cast<float>(impl_->size.x), static_cast<float>(impl_->size.y));
  glUniform2f(impl_->viewportLocation, static_cast<float>(widthPixels),
              static_cast<float>(heightPixels));
  glUniform1f(impl_->opacityLocation, opacity);
  glUniform1i(impl_->textureLocation, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, impl_->texture.get());
  glBindVertexArray(impl_->vertexArray.get());
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glUseProgram(0);
  glDisable(GL_BLEND);
  glEnable(GL_CULL_FACE);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace globe::render
