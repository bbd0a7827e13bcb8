// LabelRenderer: one stream buffer a draw, icons first (a draw call per icon texture run), then
// every glyph and panel box in one call against the glyph atlas, shaders/label.*.
#include "render/label_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>

#include <glm/common.hpp>

#include "render/gl.hpp"
#include "render/gl_object.hpp"
#include "render/glyph_atlas.hpp"
#include "render/pin_icon.hpp"
#include "render/pixel_unpack.hpp"
#include "render/shader_directory.hpp"
#include "render/shader_program.hpp"
#include "text/text_wrap.hpp"

namespace globe::render {
// Named, not anonymous: Impl's members use these types.
namespace label_detail {

struct LabelVertex {
  glm::vec2 positionPixels;
  glm::vec2 texel;  // in texels of the bound texture
  glm::vec4 rgba;
  glm::vec4 haloRgba;
};

struct IconTexture {
  GlObject texture;
  glm::ivec2 sizePixels;
};

void appendLabelQuad(std::vector<LabelVertex>& out, glm::vec2 minPixels, glm::vec2 maxPixels,
                     glm::vec2 minTexel, glm::vec2 maxTexel, const glm::vec4& rgba,
                     const glm::vec4& haloRgba) {
  const LabelVertex a{minPixels, minTexel, rgba, haloRgba};
  const LabelVertex b{{maxPixels.x, minPixels.y}, {maxTexel.x, minTexel.y}, rgba, haloRgba};
  const LabelVertex c{maxPixels, maxTexel, rgba, haloRgba};
  const LabelVertex d{{minPixels.x, maxPixels.y}, {minTexel.x, maxTexel.y}, rgba, haloRgba};
  for (const LabelVertex& v : {a, b, c, a, c, d}) out.push_back(v);
}

// One line of shaped text to draw, its baseline's left end on whole pixels.
struct TextRun {
  text::ShapedText shaped;
  glm::vec2 baselineOriginPixels;
  float sizePixels;
  glm::vec4 rgba, haloRgba;
};

// A panel's boxes and lines, relative to its top-left corner.
struct PanelLayout {
  glm::vec2 sizePixels{0.0f};
  std::vector<TextRun> lines;
};

PanelLayout layoutPanel(const text::FontFace& font, const TextPanelStyle& style,
                        const std::vector<std::string>& paragraphs, float maxWidthPixels) {
  PanelLayout out;
  if (paragraphs.empty()) return out;
  // NaN, negative or zero: as wide as the longest paragraph.
  if (!(maxWidthPixels > 0.0f)) maxWidthPixels = std::numeric_limits<float>::infinity();
  const float pad = style.paddingPixels;
  const float textWidth = std::max(1.0f, maxWidthPixels - 2 * pad);
  float y = pad, widest = 0.0f;
  for (size_t p = 0; p < paragraphs.size(); ++p) {
    const float size = p == 0 ? style.titleSizePixels : style.bodySizePixels;
    if (p > 0) y += style.paragraphGapPixels;
    const auto widthOf = [&](std::string_view text) {
      return font.measure(text, size).widthPixels;
    };
    for (const std::string& line : text::wrapText(paragraphs[p], textWidth, widthOf)) {
      text::ShapedText shaped = font.shape(line, size);
      const text::TextExtent extent = shaped.extent;
      widest = std::max(widest, extent.widthPixels);
      out.lines.push_back({std::move(shaped),
                           {pad, std::round(y + extent.ascentPixels)},
                           size,
                           style.textRgba,
                           glm::vec4(0.0f)});
      y += extent.ascentPixels + extent.descentPixels;
    }
  }
  out.sizePixels = {std::min(maxWidthPixels, std::ceil(widest) + 2 * pad), std::ceil(y + pad)};
  return out;
}

}  // namespace label_detail

using namespace label_detail;

struct LabelRenderer::Impl {
  std::unique_ptr<text::FontFace> font;
  std::unique_ptr<GlyphAtlas> atlas;
  ShaderProgram program;
  GLint viewportLocation = -1;
  GLint textureLocation = -1;
  GLint modeLocation = -1;
  GlObject vertexArray;
  GlObject vertexBuffer;
  std::map<std::string, IconTexture, std::less<>> icons;
  TextPanelStyle panelStyle;

  // Glyph quads for the runs; false when the atlas filled up (unless skipFull: those glyphs are
  // left out).
  bool appendText(std::span<const TextRun> runs, bool skipFull, std::vector<LabelVertex>& out) {
    for (const TextRun& run : runs) {
      for (const text::ShapedGlyph& glyph : run.shaped.glyphs) {
        const std::optional<AtlasGlyph> placed = atlas->glyph(glyph.glyphId, run.sizePixels);
        if (!placed) {
          if (skipFull) continue;
          return false;
        }
        if (placed->sizePixels.x == 0) continue;
        const glm::vec2 topLeft = run.baselineOriginPixels + glm::round(glyph.originPixels) +
                                  glm::vec2(placed->offsetPixels);
        const glm::vec2 size(placed->sizePixels);
        const glm::vec2 texel(placed->texelMin);
        appendLabelQuad(out, topLeft, topLeft + size, texel, texel + size, run.rgba, run.haloRgba);
      }
    }
    return true;
  }
  // Glyph quads after `prefix` (solid boxes), refilling the atlas once if this frame's glyphs
  // do not all fit beside the earlier frames'.
  std::vector<LabelVertex> textVertices(std::span<const TextRun> runs,
                                        const std::vector<LabelVertex>& prefix) {
    std::vector<LabelVertex> out = prefix;
    if (appendText(runs, false, out)) return out;
    atlas->clear();
    out = prefix;
    appendText(runs, true, out);
    return out;
  }

  void upload(const std::vector<LabelVertex>& vertices) const {
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer.get());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(LabelVertex)),
                 vertices.empty() ? nullptr : vertices.data(), GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
  }
  void beginDraw(glm::ivec2 viewportPixels) const {
    glViewport(0, 0, viewportPixels.x, viewportPixels.y);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    // Premultiplied colour; the framebuffer's alpha stays opaque (screenshots keep no holes).
    glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glUseProgram(program.id());
    glUniform2f(viewportLocation, static_cast<float>(viewportPixels.x),
                static_cast<float>(viewportPixels.y));
    glUniform1i(textureLocation, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(vertexArray.get());
  }
  void drawRange(GLuint texture, int mode, size_t first, size_t count) const {
    if (count == 0) return;
    glBindTexture(GL_TEXTURE_2D, texture);
    glUniform1i(modeLocation, mode);
    glDrawArrays(GL_TRIANGLES, static_cast<GLint>(first), static_cast<GLsizei>(count));
  }
  void endDraw() const {
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_BLEND);
    glEnable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
  }
};

LabelRenderer::LabelRenderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
LabelRenderer::~LabelRenderer() = default;

Result<std::unique_ptr<LabelRenderer>> LabelRenderer::create(
    const std::filesystem::path& shaderDirectory) {
  auto font = text::FontFace::loadDefault();
  if (!font) return makeError(font.error());
  const std::filesystem::path dir =
      shaderDirectory.empty() ? defaultShaderDirectory() : shaderDirectory;
  auto program = loadNamedShaderProgram(dir, "label.vert", "label.frag");
  if (!program) return makeError(program.error());
  auto impl = std::make_unique<Impl>();
  impl->font = std::move(*font);
  impl->program = std::move(*program);
  impl->viewportLocation = impl->program.uniformLocation("u_viewportPixels");
  impl->textureLocation = impl->program.uniformLocation("u_texture");
  impl->modeLocation = impl->program.uniformLocation("u_mode");
  if (impl->viewportLocation < 0 || impl->textureLocation < 0 || impl->modeLocation < 0) {
    return makeError((dir / "label.vert").string() +
                     ": the program lacks u_viewportPixels, u_texture or u_mode");
  }
  impl->atlas = std::make_unique<GlyphAtlas>(*impl->font);
  impl->vertexArray = makeGlVertexArray();
  impl->vertexBuffer = makeGlBuffer();
  glBindVertexArray(impl->vertexArray.get());
  glBindBuffer(GL_ARRAY_BUFFER, impl->vertexBuffer.get());
  const auto attribute = [](GLuint index, GLint components, size_t offset) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, components, GL_FLOAT, GL_FALSE, sizeof(LabelVertex),
                          reinterpret_cast<const void*>(offset));
  };
  attribute(0, 2, offsetof(LabelVertex, positionPixels));
  attribute(1, 2, offsetof(LabelVertex, texel));
  attribute(2, 4, offsetof(LabelVertex, rgba));
  attribute(3, 4, offsetof(LabelVertex, haloRgba));
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  auto renderer = std::unique_ptr<LabelRenderer>(new LabelRenderer(std::move(impl)));
  renderer->setIcon(std::string(kPinIconKey), makePinIcon());
  return renderer;
}

void LabelRenderer::setIcon(const std::string& key, const formats::ImageRgba& image) {
  if (impl_->icons.contains(key)) return;
  const glm::ivec2 size(image.widthPixels, image.heightPixels);
  if (size.x <= 0 || size.y <= 0 || size.x > formats::kMaxDecodedImageSide ||
      size.y > formats::kMaxDecodedImageSide ||
      image.pixels.size() != static_cast<size_t>(4 * size.x * size.y)) {
    return;
  }
  // Premultiplied, so filtering (mipmaps, scaling) never bleeds transparent texels' colour in.
  std::vector<uint8_t> premultiplied(image.pixels);
  for (size_t i = 0; i < premultiplied.size(); i += 4) {
    const unsigned alpha = premultiplied[i + 3];
    for (size_t c = 0; c < 3; ++c) {
      premultiplied[i + c] = static_cast<uint8_t>((premultiplied[i + c] * alpha + 127) / 255);
    }
  }
  IconTexture icon{makeGlTexture(), size};
  glBindTexture(GL_TEXTURE_2D, icon.texture.get());
  {
    const TightUnpack tight;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.x, size.y, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 premultiplied.data());
  }
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  impl_->icons.emplace(key, std::move(icon));
}

bool LabelRenderer::hasIcon(const std::string& key) const { return impl_->icons.contains(key); }

std::vector<text::PlacedLabel> LabelRenderer::layout(std::span<const text::ScreenLabel> labels,
                                               glm::ivec2 viewportPixels) const {
  const text::FontFace& font = *impl_->font;
  return text::layoutLabels(labels, viewportPixels, [&font](const std::string& text, float size) {
    return font.measure(text, size);
  });
}

void LabelRenderer::draw(std::span<const text::ScreenLabel> labels, std::span<const text::PlacedLabel> placed,
                         glm::ivec2 viewportPixels) {
  if (viewportPixels.x <= 0 || viewportPixels.y <= 0) return;
  std::vector<LabelVertex> vertices;
  struct IconRun {
    GLuint texture;
    size_t first, count;
  };
  std::vector<IconRun> iconRuns;
  std::vector<TextRun> runs;
  for (const text::PlacedLabel& place : placed) {
    if (place.index >= labels.size()) continue;
    const text::ScreenLabel& label = labels[place.index];
    text::ShapedText shaped;
    if (place.withText) shaped = impl_->font->shape(label.text, label.sizePixels);
    const text::LabelGeometry geometry = text::labelGeometry(label, shaped.extent);
    const auto icon = impl_->icons.find(label.iconKey);
    if (geometry.hasIcon && icon != impl_->icons.end()) {
      const GLuint texture = icon->second.texture.get();
      if (iconRuns.empty() || iconRuns.back().texture != texture) {
        iconRuns.push_back({texture, vertices.size(), 0});
      }
      appendLabelQuad(vertices, geometry.iconMinPixels, geometry.iconMaxPixels, glm::vec2(0.0f),
                      glm::vec2(icon->second.sizePixels), label.iconRgba, glm::vec4(0.0f));
      iconRuns.back().count += 6;
    }
    if (geometry.hasText) {
      runs.push_back({std::move(shaped), geometry.baselineOriginPixels, label.sizePixels,
                      label.textRgba, label.haloRgba});
    }
  }
  const size_t textFirst = vertices.size();
  vertices = impl_->textVertices(runs, vertices);
  if (vertices.empty()) return;
  impl_->upload(vertices);
  impl_->beginDraw(viewportPixels);
  for (const IconRun& run : iconRuns) impl_->drawRange(run.texture, 1, run.first, run.count);
  impl_->drawRange(impl_->atlas->texture(), 0, textFirst, vertices.size() - textFirst);
  impl_->endDraw();
}

glm::vec2 LabelRenderer::textPanelSizePixels(const std::vector<std::string>& paragraphs,
                                             float maxWidthPixels) const {
  return layoutPanel(*impl_->font, impl_->panelStyle, paragraphs, maxWidthPixels).sizePixels;
}

void LabelRenderer::drawTextPanel(const std::vector<std::string>& paragraphs,
                                  glm::vec2 topLeftPixels, float maxWidthPixels,
                                  glm::ivec2 viewportPixels) {
  if (viewportPixels.x <= 0 || viewportPixels.y <= 0) return;
  if (!std::isfinite(topLeftPixels.x) || !std::isfinite(topLeftPixels.y)) return;
  PanelLayout panel = layoutPanel(*impl_->font, impl_->panelStyle, paragraphs, maxWidthPixels);
  if (panel.lines.empty()) return;
  const glm::vec2 origin = glm::round(topLeftPixels);
  for (TextRun& line : panel.lines) line.baselineOriginPixels += origin;
  // The box samples the atlas's solid block: one draw call with the text over it.
  std::vector<LabelVertex> box;
  const glm::vec2 solid = impl_->atlas->solidTexel();
  appendLabelQuad(box, origin, origin + panel.sizePixels, solid, solid,
                  impl_->panelStyle.backgroundRgba, glm::vec4(0.0f));
  const std::vector<LabelVertex> vertices = impl_->textVertices(panel.lines, box);
  impl_->upload(vertices);
  impl_->beginDraw(viewportPixels);
  impl_->drawRange(impl_->atlas->texture(), 0, 0, vertices.size());
  impl_->endDraw();
}


const text::FontFace& LabelRenderer::font() const { return *impl_->font; }

}  // namespace globe::render
