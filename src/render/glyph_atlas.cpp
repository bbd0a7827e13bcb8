// GlyphAtlas: a CPU copy of the texels beside the texture, so growing re-uploads it whole and
// each new glyph uploads only its own rectangle.
#include "render/glyph_atlas.hpp"

#include <algorithm>
#include <cstring>

#include "text/label_layout.hpp"
#include "render/pixel_unpack.hpp"

namespace globe::render {
namespace {

constexpr int kGlyphPaddingPixels = 1;  // between glyphs, so filtering never mixes neighbours

}  // namespace

std::optional<glm::ivec2> ShelfPacker::insert(glm::ivec2 sizePixels) {
  if (sizePixels.x <= 0 || sizePixels.y <= 0 || sizePixels.x > sidePixels_ ||
      sizePixels.y > sidePixels_) {
    return std::nullopt;
  }
  // The lowest shelf that takes it without wasting more than half its height, else a new shelf,
  // else any shelf that takes it.
  Shelf* best = nullptr;
  Shelf* any = nullptr;
  for (Shelf& shelf : shelves_) {
    if (shelf.heightPixels < sizePixels.y || shelf.usedWidthPixels + sizePixels.x > sidePixels_) {
      continue;
    }
    if (any == nullptr || shelf.heightPixels < any->heightPixels) any = &shelf;
    if (2 * sizePixels.y >= shelf.heightPixels &&
        (best == nullptr || shelf.heightPixels < best->heightPixels)) {
      best = &shelf;
    }
  }
  const int nextY = shelves_.empty() ? 0 : shelves_.back().yPixels + shelves_.back().heightPixels;
  if (best == nullptr && nextY + sizePixels.y <= sidePixels_) {
    shelves_.push_back({nextY, sizePixels.y, 0});
    best = &shelves_.back();
  }
  if (best == nullptr) best = any;
  if (best == nullptr) return std::nullopt;
  const glm::ivec2 at(best->usedWidthPixels, best->yPixels);
  best->usedWidthPixels += sizePixels.x;
  return at;
}

GlyphAtlas::GlyphAtlas(const text::FontFace& font)
    : font_(font), texture_(makeGlTexture()), packer_(kInitialSidePixels) {
  texels_.assign(static_cast<size_t>(2 * kInitialSidePixels * kInitialSidePixels), 0);
  glBindTexture(GL_TEXTURE_2D, texture_.get());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  reserveSolidBlock();
  uploadAll();
}

void GlyphAtlas::reserveSolidBlock() {
  const std::optional<glm::ivec2> at = packer_.insert(glm::ivec2(2 + kGlyphPaddingPixels));
  if (!at) return;  // cannot happen: the packer is empty
  const int side = packer_.sidePixels();
  for (int y = 0; y < 2; ++y) {
    std::fill_n(&texels_[static_cast<size_t>(2 * ((at->y + y) * side + at->x))], 4, uint8_t{255});
  }
}

void GlyphAtlas::uploadAll() {
  const int side = packer_.sidePixels();
  glBindTexture(GL_TEXTURE_2D, texture_.get());
  {
    const TightUnpack tight(side);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG8, side, side, 0, GL_RG, GL_UNSIGNED_BYTE, texels_.data());
  }
  glBindTexture(GL_TEXTURE_2D, 0);
}

bool GlyphAtlas::growTexture() {
  const int side = packer_.sidePixels();
  if (side * 2 > kMaxSidePixels) return false;
  std::vector<uint8_t> grown(static_cast<size_t>(2 * (2 * side) * (2 * side)), 0);
  for (int y = 0; y < side; ++y) {
    std::memcpy(&grown[static_cast<size_t>(2 * y * 2 * side)],
                &texels_[static_cast<size_t>(2 * y * side)], static_cast<size_t>(2 * side));
  }
  texels_ = std::move(grown);
  packer_.grow(2 * side);
  uploadAll();
  return true;
}

void GlyphAtlas::clear() {
  glyphs_.clear();
  packer_.clear();
  std::fill(texels_.begin(), texels_.end(), uint8_t{0});
  reserveSolidBlock();
  uploadAll();
}

std::optional<AtlasGlyph> GlyphAtlas::glyph(uint32_t glyphId, float sizePixels) {
  const Key key{glyphId, text::labelPixelSize(sizePixels)};
  if (const auto found = glyphs_.find(key); found != glyphs_.end()) return found->second;
  const text::GlyphBitmap bitmap =
      font_.rasterize(glyphId, sizePixels, text::labelHaloPixels(static_cast<float>(key.pixelSize)));
  AtlasGlyph placed;
  if (bitmap.widthPixels > 0 && bitmap.heightPixels > 0) {
    const glm::ivec2 size(bitmap.widthPixels, bitmap.heightPixels);
    std::optional<glm::ivec2> at = packer_.insert(size + kGlyphPaddingPixels);
    while (!at && growTexture()) at = packer_.insert(size + kGlyphPaddingPixels);
    if (!at) return std::nullopt;
    const int side = packer_.sidePixels();
    for (int y = 0; y < size.y; ++y) {
      std::memcpy(&texels_[static_cast<size_t>(2 * ((at->y + y) * side + at->x))],
                  &bitmap.fillAndHalo[static_cast<size_t>(2 * y * size.x)],
                  static_cast<size_t>(2 * size.x));
    }
    glBindTexture(GL_TEXTURE_2D, texture_.get());
    {
      const TightUnpack tight(side);
      glTexSubImage2D(GL_TEXTURE_2D, 0, at->x, at->y, size.x, size.y, GL_RG, GL_UNSIGNED_BYTE,
                      &texels_[static_cast<size_t>(2 * (at->y * side + at->x))]);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    placed = {*at, size, bitmap.offsetPixels};
  }
  glyphs_.emplace(key, placed);
  return placed;
}

}  // namespace globe::render
