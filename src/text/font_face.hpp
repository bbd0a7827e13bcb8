// The label font: found on disk, shaped with HarfBuzz and rasterised with FreeType, all on the
// CPU, so callers can measure and lay out text without a GL context.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "core/result.hpp"

namespace globe::text {

// $GLOBE_FONT when set and non-empty, else DejaVuSans-Bold.ttf or DejaVuSans.ttf in
// /usr/share/fonts/truetype/dejavu. The error names what was looked for and the Debian package.
Result<std::filesystem::path> findLabelFont();

// Text sizes are whole pixels (1..256) so shaping, measuring and the glyph atlas agree; 0 for a
// size that is not a finite positive number (nothing is drawn).
int labelPixelSize(float sizePixels);

// The line box of a shaped text: the advance and the font's ascent and descent (both >= 0, the
// same for any text of one size, so labels of one size line up).
struct TextExtent {
  float widthPixels = 0.0f;
  float ascentPixels = 0.0f;
  float descentPixels = 0.0f;
};

struct ShapedGlyph {
  uint32_t glyphId = 0;      // 0: the font's .notdef box (a character the font lacks)
  glm::vec2 originPixels{};  // where the glyph's origin lies, from the text's left baseline, y down
  uint32_t clusterByte = 0;  // the UTF-8 byte offset of the character(s) it draws
};

// Glyphs in visual order, left to right: right-to-left text (Arabic, Hebrew) comes out reversed
// with respect to its bytes.
struct ShapedText {
  std::vector<ShapedGlyph> glyphs;
  TextExtent extent;
  bool rightToLeft = false;
};

// One glyph's coverage and halo, two bytes a pixel, rows top-down: the glyph's coverage, then the
// coverage of the glyph grown by the halo radius (so the halo byte is >= the glyph byte).
struct GlyphBitmap {
  int widthPixels = 0;  // 0 for a blank glyph (a space)
  int heightPixels = 0;
  glm::ivec2 offsetPixels{};  // the bitmap's top-left from the glyph origin, y down
  std::vector<uint8_t> fillAndHalo;
};

// One font file. Not thread-safe (FreeType and HarfBuzz keep the current size in the face).
class FontFace {
 public:
  static Result<std::unique_ptr<FontFace>> load(const std::filesystem::path& fontPath);
  // load(findLabelFont()).
  static Result<std::unique_ptr<FontFace>> loadDefault();
  ~FontFace();
  FontFace(const FontFace&) = delete;
  FontFace& operator=(const FontFace&) = delete;

  const std::filesystem::path& path() const;

  // Shapes UTF-8 (script, language and direction guessed from the text); invalid bytes become
  // U+FFFD, which the font may draw as its .notdef box.
  ShapedText shape(std::string_view utf8, float sizePixels) const;
  TextExtent measure(std::string_view utf8, float sizePixels) const;

  // Renders a glyph at labelPixelSize(sizePixels) with FreeType (light hinting: crisp baselines,
  // unchanged advances) and its halo with FT_Stroker.
  GlyphBitmap rasterize(uint32_t glyphId, float sizePixels, float haloPixels) const;

 private:
  struct Impl;
  explicit FontFace(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace globe::text
