// HUD text: stb_easy_font quads → triangles in a stream buffer, drawn with shaders/hud.*.
#include "render/hud_renderer.hpp"

#include <algorithm>
#include <cstddef>

#include "render/gl.hpp"
#include "render/gl_object.hpp"
#include "render/shader_directory.hpp"
#include "render/shader_program.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

namespace globe::render {
namespace {

constexpr float kLineFontPixels = 12.0f;  // stb_easy_font's line advance

// stb_easy_font's vertex: x, y, z floats and four colour bytes.
struct FontVertex {
  float x, y, z;
  unsigned char rgba[4];
};

void appendQuad(std::vector<HudVertex>& out, glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d,
                const glm::vec4& rgba) {
  for (const glm::vec2& p : {a, b, c, a, c, d}) out.push_back({p, rgba});
}

// What stb's font can draw: printable ASCII, and newlines it lays out. Anything else (a UTF-8
// place name, a control byte) is one '?' per character; stb would read before its glyph table.
std::string drawableText(const std::string& line) {
  std::string text;
  for (size_t i = 0; i < line.size(); ++i) {
    const auto c = static_cast<unsigned char>(line[i]);
    if (c >= 0x80) {
      if ((c & 0xC0U) == 0x80U) continue;  // a continuation byte of the '?' already written
      text.push_back('?');
    } else {
      text.push_back(c >= 0x20 && c < 0x7F ? static_cast<char>(c) : '?');
    }
  }
  return text;
}

int lineWidthFontPixels(const std::string& line) {
  std::string text = drawableText(line);  // stb wants a mutable string
  return stb_easy_font_width(text.data());
}

}  // namespace

glm::vec2 hudBlockSizePixels(const HudTextBlock& block) {
  int widest = 0;
  for (const std::string& line : block.lines) widest = std::max(widest, lineWidthFontPixels(line));
  const float lines = static_cast<float>(block.lines.size());
  return {static_cast<float>(widest) * block.scale + 2 * block.paddingPixels,
          lines * kLineFontPixels * block.scale + 2 * block.paddingPixels - 3 * block.scale};
}

namespace {

void appendBlock(std::vector<HudVertex>& out, std::vector<FontVertex>& quads,
                 const HudTextBlock& block) {
  if (block.lines.empty()) return;
  const glm::vec2 size = hudBlockSizePixels(block);
  const glm::vec2 p = block.topLeftPixels;
  if (block.backgroundRgba.a > 0) {
    appendQuad(out, p, {p.x + size.x, p.y}, p + size, {p.x, p.y + size.y}, block.backgroundRgba);
  }
  for (size_t row = 0; row < block.lines.size(); ++row) {
    std::string text = drawableText(block.lines[row]);
    quads.resize(text.size() * 80 + 16);  // stb uses ~270 bytes (17 vertices) a character
    const int count = stb_easy_font_print(0, 0, text.data(), nullptr, quads.data(),
                                          static_cast<int>(quads.size() * sizeof(FontVertex)));
    const glm::vec2 origin =
        p + glm::vec2(block.paddingPixels, block.paddingPixels + static_cast<float>(row) *
                                                                     kLineFontPixels * block.scale);
    for (int q = 0; q < count; ++q) {
      glm::vec2 corner[4];
      for (int k = 0; k < 4; ++k) {
        const FontVertex& v = quads[static_cast<size_t>(4 * q + k)];
        corner[k] = origin + block.scale * glm::vec2(v.x, v.y);
      }
      appendQuad(out, corner[0], corner[1], corner[2], corner[3], block.textRgba);
    }
  }
}

}  // namespace

std::vector<HudVertex> buildHudTriangles(std::span<const HudItem> items) {
  std::vector<HudVertex> out;
  std::vector<FontVertex> quads;
  for (const HudItem& item : items) {
    if (const auto* block = std::get_if<HudTextBlock>(&item)) {
      appendBlock(out, quads, *block);
    } else {
      const HudShape& shape = std::get<HudShape>(item);
      const size_t whole = shape.trianglesPixels.size() / 3 * 3;
      for (size_t i = 0; i < whole; ++i) out.push_back({shape.trianglesPixels[i], shape.rgba});
    }
  }
  return out;
}

std::vector<HudVertex> buildHudTriangles(std::span<const HudTextBlock> blocks) {
  const std::vector<HudItem> items(blocks.begin(), blocks.end());
  return buildHudTriangles(items);
}

struct HudRenderer::Impl {
  ShaderProgram program;
  GLint viewportLocation = -1;
  GlObject vertexArray;
  GlObject vertexBuffer;
  GLsizei vertexCount = 0;
};

HudRenderer::HudRenderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
HudRenderer::~HudRenderer() = default;

Result<std::unique_ptr<HudRenderer>> HudRenderer::create(
    const std::filesystem::path& shaderDirectory) {
  const std::filesystem::path dir =
      shaderDirectory.empty() ? defaultShaderDirectory() : shaderDirectory;
  auto program = loadNamedShaderProgram(dir, "hud.vert", "hud.frag");
  if (!program) return makeError(program.error());
  auto impl = std::make_unique<Impl>();
  impl->program = std::move(*program);
  impl->viewportLocation = impl->program.uniformLocation("u_viewportPixels");
  if (impl->viewportLocation < 0) {
    return makeError((dir / "hud.vert").string() + ": the program lacks u_viewportPixels");
  }
  impl->vertexArray = makeGlVertexArray();
  impl->vertexBuffer = makeGlBuffer();
  glBindVertexArray(impl->vertexArray.get());
  glBindBuffer(GL_ARRAY_BUFFER, impl->vertexBuffer.get());
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(HudVertex),
                        reinterpret_cast<const void*>(offsetof(HudVertex, positionPixels)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(HudVertex),
                        reinterpret_cast<const void*>(offsetof(HudVertex, rgba)));
  glBindVertexArray(0);
  return std::unique_ptr<HudRenderer>(new HudRenderer(std::move(impl)));
}

void HudRenderer::setItems(std::span<const HudItem> items) {
  const std::vector<HudVertex> vertices = buildHudTriangles(items);
  glBindBuffer(GL_ARRAY_BUFFER, impl_->vertexBuffer.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(HudVertex)),
               vertices.empty() ? nullptr : vertices.data(), GL_DYNAMIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  impl_->vertexCount = static_cast<GLsizei>(vertices.size());
}

void HudRenderer::draw(int widthPixels, int heightPixels) const {
  if (impl_->vertexCount == 0 || widthPixels <= 0 || heightPixels <= 0) return;
  glViewport(0, 0, widthPixels, heightPixels);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  // Colour blends; the framebuffer's alpha stays opaque (screenshots keep no holes).
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  glUseProgram(impl_->program.id());
  glUniform2f(impl_->viewportLocation, static_cast<float>(widthPixels),
              static_cast<float>(heightPixels));
  glBindVertexArray(impl_->vertexArray.get());
  glDrawArrays(GL_TRIANGLES, 0, impl_->vertexCount);
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_BLEND);
  glEnable(GL_CULL_FACE);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace globe::render
