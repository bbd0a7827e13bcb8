// Label glyphs rasterised once (FontFace::rasterize) and kept in one GL texture, packed in
// shelves. Two channels, GL_RG8: the glyph's coverage and its halo's (the glyph grown by a
// stroke). Rendered coverage rather than a distance field: labels are drawn at the size they were
// rasterised at, pixel-snapped, so the bitmaps are exact and need no shader reconstruction.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <unordered_map>
#include <vector>

#include <glm/vec2.hpp>

#include "text/font_face.hpp"
#include "render/gl_object.hpp"

namespace globe::render {

// Shelf packing of rectangles into a square that may grow (the shelves stay where they are).
class ShelfPacker {
 public:
  explicit ShelfPacker(int sidePixels) : sidePixels_(sidePixels) {}
  // The top-left of a free sizePixels rectangle, or nullopt when none is left.
  std::optional<glm::ivec2> insert(glm::ivec2 sizePixels);
  void grow(int sidePixels) { sidePixels_ = sidePixels; }
  void clear() { shelves_.clear(); }
  int sidePixels() const { return sidePixels_; }

 private:
  struct Shelf {
    int yPixels, heightPixels, usedWidthPixels;
  };
  int sidePixels_;
  std::vector<Shelf> shelves_;
};

// Where a glyph lies in the atlas and how to place it.
struct AtlasGlyph {
  glm::ivec2 texelMin{};      // top-left texel
  glm::ivec2 sizePixels{};    // (0, 0) for a blank glyph
  glm::ivec2 offsetPixels{};  // the bitmap's top-left from the glyph origin, y down
};

// Needs a current GL 3.3 core context for its whole life.
class GlyphAtlas {
 public:
  static constexpr int kInitialSidePixels = 1024;
  static constexpr int kMaxSidePixels = 4096;

  explicit GlyphAtlas(const text::FontFace& font);

  // The glyph at labelPixelSize(sizePixels) with the halo labelHaloPixels(sizePixels),
  // rasterised and uploaded on first use. The atlas doubles when full, up to kMaxSidePixels;
  // nullopt when even that is full: clear() and ask again for what the frame needs.
  std::optional<AtlasGlyph> glyph(uint32_t glyphId, float sizePixels);
  // Forgets every glyph (their texels are reused).
  void clear();

  GLuint texture() const { return texture_.get(); }
  int sidePixels() const { return packer_.sidePixels(); }
  size_t glyphCount() const { return glyphs_.size(); }
  // The centre of a 2×2 block whose glyph and halo coverage are full: quads sampling it draw
  // solid colour (text panel backgrounds) in the same draw call as the text.
  glm::vec2 solidTexel() const { return {1.0f, 1.0f}; }

 private:
  void reserveSolidBlock();
  void uploadAll();
  bool growTexture();

  const text::FontFace& font_;
  GlObject texture_;
  ShelfPacker packer_;
  std::vector<uint8_t> texels_;  // a copy of the texture (2 bytes a texel), to grow it
  struct Key {
    uint32_t glyphId;
    int pixelSize;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    size_t operator()(const Key& key) const {
      return std::hash<uint64_t>()((uint64_t{key.glyphId} << 16) ^ uint64_t(key.pixelSize));
    }
  };
  std::unordered_map<Key, AtlasGlyph, KeyHash> glyphs_;
};

}  // namespace globe::render
