// FontFace: HarfBuzz shapes from the font file's own tables (its default OpenType functions, at
// scale = pixels·64), FreeType rasterises; both open the same file.
#include "text/font_face.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <string>
#include <system_error>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_GLYPH_H
#include FT_STROKER_H
#include <hb.h>

namespace globe::text {
namespace {

constexpr const char* kDejaVuDirectory = "/usr/share/fonts/truetype/dejavu";
constexpr const char* kDejaVuFiles[] = {"DejaVuSans-Bold.ttf", "DejaVuSans.ttf"};
constexpr int kMaxLabelPixelSize = 256;
constexpr size_t kMaxShapedBytes = 1 << 20;  // HarfBuzz counts in int; labels are far shorter

bool isFile(const std::filesystem::path& path) {
  std::error_code error;
  return std::filesystem::is_regular_file(path, error);
}

// Row `row` (top-down) of a FreeType bitmap, whichever way its pitch runs.
const uint8_t* bitmapRow(const FT_Bitmap& bitmap, unsigned row) {
  const auto pitch = static_cast<ptrdiff_t>(bitmap.pitch);
  if (pitch >= 0) return bitmap.buffer + static_cast<ptrdiff_t>(row) * pitch;
  return bitmap.buffer + static_cast<ptrdiff_t>(bitmap.rows - 1 - row) * -pitch;
}

// Renders an outline glyph (consumed) to 8-bit coverage; nullptr when FreeType cannot.
FT_BitmapGlyph renderGlyph(FT_Glyph glyph) {
  if (FT_Glyph_To_Bitmap(&glyph, FT_RENDER_MODE_NORMAL, nullptr, 1) != 0) {
    FT_Done_Glyph(glyph);
    return nullptr;
  }
  auto* bitmap = reinterpret_cast<FT_BitmapGlyph>(glyph);
  if (bitmap->bitmap.pixel_mode != FT_PIXEL_MODE_GRAY) {
    FT_Done_Glyph(glyph);
    return nullptr;
  }
  return bitmap;
}

// Adds `source` into channel `channel` of `out` (2 bytes a pixel) by maximum.
void addCoverage(GlyphBitmap& out, FT_BitmapGlyph source, int channel) {
  const FT_Bitmap& bitmap = source->bitmap;
  const int x0 = source->left - out.offsetPixels.x;
  const int y0 = -source->top - out.offsetPixels.y;
  for (unsigned row = 0; row < bitmap.rows; ++row) {
    const uint8_t* in = bitmapRow(bitmap, row);
    uint8_t* line = &out.fillAndHalo[static_cast<size_t>(
        2 * ((y0 + static_cast<int>(row)) * out.widthPixels + x0) + channel)];
    for (unsigned x = 0; x < bitmap.width; ++x) {
      line[2 * x] = std::max(line[2 * x], in[x]);
    }
  }
}

}  // namespace

Result<std::filesystem::path> findLabelFont() {
  if (const char* env = std::getenv("GLOBE_FONT"); env != nullptr && *env != '\0') {
    if (isFile(env)) return std::filesystem::path(env);
    return makeError(std::string("$GLOBE_FONT=") + env + ": no such font file");
  }
  std::string tried;
  for (const char* name : kDejaVuFiles) {
    const std::filesystem::path path = std::filesystem::path(kDejaVuDirectory) / name;
    if (isFile(path)) return path;
    tried += (tried.empty() ? "" : " nor ") + path.string();
  }
  return makeError("no label font: $GLOBE_FONT is unset and neither " + tried +
                   " exists (install the Debian package fonts-dejavu-core)");
}

int labelPixelSize(float sizePixels) {
  if (!std::isfinite(sizePixels) || sizePixels <= 0.0f) return 0;
  return std::clamp(static_cast<int>(std::lround(sizePixels)), 1, kMaxLabelPixelSize);
}

struct FontFace::Impl {
  std::filesystem::path path;
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  FT_Stroker stroker = nullptr;
  hb_blob_t* blob = nullptr;
  hb_face_t* hbFace = nullptr;
  hb_font_t* font = nullptr;

  ~Impl() {
    if (font != nullptr) hb_font_destroy(font);
    if (hbFace != nullptr) hb_face_destroy(hbFace);
    if (blob != nullptr) hb_blob_destroy(blob);
    if (stroker != nullptr) FT_Stroker_Done(stroker);
    if (face != nullptr) FT_Done_Face(face);
    if (library != nullptr) FT_Done_FreeType(library);
  }
  // Sets HarfBuzz's scale to `pixels` and returns the font's ascent and descent at it.
  TextExtent setSize(int pixels) const {
    hb_font_set_scale(font, pixels * 64, pixels * 64);
    hb_font_extents_t extents{};
    hb_font_get_h_extents(font, &extents);
    return {0.0f, static_cast<float>(extents.ascender) / 64.0f,
            static_cast<float>(-extents.descender) / 64.0f};
  }
};

FontFace::FontFace(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
FontFace::~FontFace() = default;

Result<std::unique_ptr<FontFace>> FontFace::load(const std::filesystem::path& fontPath) {
  auto impl = std::make_unique<Impl>();
  impl->path = fontPath;
  const std::string name = fontPath.string();
  if (FT_Init_FreeType(&impl->library) != 0) return makeError("FreeType failed to initialise");
  if (const FT_Error error = FT_New_Face(impl->library, name.c_str(), 0, &impl->face); error != 0) {
    return makeError(name + ": FreeType cannot open the font (error " + std::to_string(error) +
                     ")");
  }
  if (!FT_IS_SCALABLE(impl->face)) return makeError(name + ": not a scalable (outline) font");
  if (FT_Stroker_New(impl->library, &impl->stroker) != 0) {
    return makeError("FreeType failed to create a stroker");
  }
  impl->blob = hb_blob_create_from_file_or_fail(name.c_str());
  if (impl->blob == nullptr) return makeError(name + ": HarfBuzz cannot read the font");
  impl->hbFace = hb_face_create(impl->blob, 0);
  impl->font = hb_font_create(impl->hbFace);
  if (hb_face_get_glyph_count(impl->hbFace) == 0) {
    return makeError(name + ": HarfBuzz finds no glyphs in the font");
  }
  return std::unique_ptr<FontFace>(new FontFace(std::move(impl)));
}

Result<std::unique_ptr<FontFace>> FontFace::loadDefault() {
  auto path = findLabelFont();
  if (!path) return makeError(path.error());
  return load(*path);
}

const std::filesystem::path& FontFace::path() const { return impl_->path; }

ShapedText FontFace::shape(std::string_view utf8, float sizePixels) const {
  ShapedText out;
  const int pixels = labelPixelSize(sizePixels);
  if (pixels == 0) return out;
  out.extent = impl_->setSize(pixels);
  if (utf8.empty()) return out;
  const int length = static_cast<int>(std::min(utf8.size(), kMaxShapedBytes));
  std::unique_ptr<hb_buffer_t, decltype(&hb_buffer_destroy)> buffer(hb_buffer_create(),
                                                                    &hb_buffer_destroy);
  hb_buffer_add_utf8(buffer.get(), utf8.data(), length, 0, length);
  hb_buffer_guess_segment_properties(buffer.get());
  hb_shape(impl_->font, buffer.get(), nullptr, 0);
  out.rightToLeft = hb_buffer_get_direction(buffer.get()) == HB_DIRECTION_RTL;
  unsigned count = 0;
  const hb_glyph_info_t* infos = hb_buffer_get_glyph_infos(buffer.get(), &count);
  const hb_glyph_position_t* positions = hb_buffer_get_glyph_positions(buffer.get(), &count);
  out.glyphs.reserve(count);
  hb_position_t penX = 0, penY = 0;  // 26.6, y up
  for (unsigned i = 0; i < count; ++i) {
    const float x = static_cast<float>(penX + positions[i].x_offset) / 64.0f;
    const float y = static_cast<float>(penY + positions[i].y_offset) / 64.0f;
    out.glyphs.push_back({infos[i].codepoint, {x, -y}, infos[i].cluster});
    penX += positions[i].x_advance;
    penY += positions[i].y_advance;
  }
  out.extent.widthPixels = static_cast<float>(penX) / 64.0f;
  return out;
}

TextExtent FontFace::measure(std::string_view utf8, float sizePixels) const {
  return shape(utf8, sizePixels).extent;
}

GlyphBitmap FontFace::rasterize(uint32_t glyphId, float sizePixels, float haloPixels) const {
  const int pixels = labelPixelSize(sizePixels);
  FT_Face face = impl_->face;
  if (pixels == 0 || FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(pixels)) != 0) return {};
  if (FT_Load_Glyph(face, glyphId, FT_LOAD_NO_BITMAP | FT_LOAD_TARGET_LIGHT) != 0) return {};
  if (face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) return {};
  FT_Glyph outline = nullptr;
  if (FT_Get_Glyph(face->glyph, &outline) != 0) return {};
  // The halo is the stroke of both sides of the outline, radius haloPixels, united with the glyph
  // (below): the glyph grown by the radius, holes included.
  FT_Glyph stroked = nullptr;
  const bool withHalo = std::isfinite(haloPixels) && haloPixels > 0.0f;
  if (withHalo && FT_Glyph_Copy(outline, &stroked) == 0) {
    FT_Stroker_Set(impl_->stroker, static_cast<FT_Fixed>(std::lround(haloPixels * 64.0f)),
                   FT_STROKER_LINECAP_ROUND, FT_STROKER_LINEJOIN_ROUND, 0);
    if (FT_Glyph_Stroke(&stroked, impl_->stroker, 1) != 0) {  // keeps the copy when it fails
      FT_Done_Glyph(stroked);
      stroked = nullptr;
    }
  }
  FT_BitmapGlyph fill = renderGlyph(outline);
  FT_BitmapGlyph halo = stroked != nullptr ? renderGlyph(stroked) : nullptr;
  GlyphBitmap out;
  if (fill != nullptr) {
    int left = INT_MAX, top = INT_MAX, right = INT_MIN, bottom = INT_MIN;
    for (FT_BitmapGlyph part : {fill, halo}) {
      if (part == nullptr || part->bitmap.width == 0 || part->bitmap.rows == 0) continue;
      left = std::min(left, part->left);
      top = std::min(top, -part->top);
      right = std::max(right, part->left + static_cast<int>(part->bitmap.width));
      bottom = std::max(bottom, -part->top + static_cast<int>(part->bitmap.rows));
    }
    if (left < right && top < bottom) {
      out.widthPixels = right - left;
      out.heightPixels = bottom - top;
      out.offsetPixels = {left, top};
      out.fillAndHalo.assign(static_cast<size_t>(2 * out.widthPixels * out.heightPixels), 0);
      addCoverage(out, fill, 0);
      addCoverage(out, fill, 1);
      if (halo != nullptr) addCoverage(out, halo, 1);
    }
  }
  if (fill != nullptr) FT_Done_Glyph(reinterpret_cast<FT_Glyph>(fill));
  if (halo != nullptr) FT_Done_Glyph(reinterpret_cast<FT_Glyph>(halo));
  return out;
}

}  // namespace globe::text
