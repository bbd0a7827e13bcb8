// The compass rose and the scale bar, drawn by the real HUD renderer into an OSMesa framebuffer
// and read back: the red needle lies toward north on the screen for any heading, the scale bar
// spans the length asked, and everything stays inside the box a click is tested against.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

#include <glm/geometric.hpp>

#include "render/gl.hpp"
#include "render/hud_renderer.hpp"
#include "render/hud_widgets.hpp"
#include "render/osmesa_context.hpp"
#include "render/read_pixels.hpp"

namespace globe::render {
namespace {

constexpr int kSize = 200;

struct Drawn {
  std::vector<uint8_t> rgba;  // rows top-down
  bool red(int x, int y) const {
    const uint8_t* p = &rgba[static_cast<size_t>(4 * (y * kSize + x))];
    return p[0] > 180 && p[1] < 90 && p[2] < 90;
  }
  bool light(int x, int y) const {
    const uint8_t* p = &rgba[static_cast<size_t>(4 * (y * kSize + x))];
    return p[0] > 200 && p[1] > 200 && p[2] > 200;
  }
};

Drawn draw(const std::vector<HudItem>& items) {
  auto context = OsMesaContext::create(kSize, kSize);
  EXPECT_TRUE(context) << (context ? "" : context.error());
  if (!context) return {};
  auto hud = HudRenderer::create({});
  EXPECT_TRUE(hud) << (hud ? "" : hud.error());
  if (!hud) return {};
  glClearColor(0.2f, 0.5f, 0.3f, 1.0f);  // a green "terrain"
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  (*hud)->setItems(items);
  (*hud)->draw(kSize, kSize);
  return {readPixelsRgba(kSize, kSize)};
}

TEST(HudWidgets, TheRedNeedlePointsNorthOnTheScreenAtEveryHeading) {
  const glm::dvec2 centre(100, 100);
  for (double headingDegrees : {0.0, 30.0, 90.0, 135.0, 180.0, 250.0, 315.0}) {
    const double north = -headingDegrees * std::numbers::pi / 180;  // clockwise from up
    const Drawn image = draw(compassRose(glm::vec2(centre), 60.0f, 2.0f, north));
    ASSERT_FALSE(image.rgba.empty());
    glm::dvec2 sum(0.0);
    int count = 0, outside = 0;
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        const size_t at = static_cast<size_t>(4 * (y * kSize + x));
        const bool drawn = !std::equal(&image.rgba[at], &image.rgba[at] + 3, &image.rgba[0]);
        if (drawn && glm::distance(glm::dvec2(x + 0.5, y + 0.5), centre) > 61) ++outside;
        if (!image.red(x, y)) continue;
        sum += glm::dvec2(x + 0.5, y + 0.5);
        ++count;
      }
    }
    ASSERT_GT(count, 100) << headingDegrees;
    const glm::dvec2 toward = glm::normalize(sum / static_cast<double>(count) - centre);
    const glm::dvec2 wanted(std::sin(north), -std::cos(north));  // y down
    EXPECT_GT(glm::dot(toward, wanted), std::cos(0.05)) << headingDegrees;
    EXPECT_EQ(outside, 0) << "drawn outside the rose's disc at " << headingDegrees;
  }
}

TEST(HudWidgets, TheScaleBarSpansItsLengthAndCarriesItsLabel) {
  const Drawn image = draw(scaleBar({20.0f, 150.0f}, 120.0f, "2 km", 2.0f));
  ASSERT_FALSE(image.rgba.empty());
  // Along the bar's middle row: light from x = 20 to 140, not beyond.
  int first = kSize, last = -1;
  for (int x = 0; x < kSize; ++x) {
    if (image.light(x, 148)) {
      first = std::min(first, x);
      last = std::max(last, x);
    }
  }
  EXPECT_EQ(first, 20);
  EXPECT_EQ(last, 139);
  // The label's glyphs above the bar's middle.
  int glyphPixels = 0;
  for (int y = 110; y < 140; ++y) {
    for (int x = 60; x < 100; ++x) glyphPixels += image.light(x, y) ? 1 : 0;
  }
  EXPECT_GT(glyphPixels, 30);
  // A non-finite length draws an empty bar, not garbage.
  const auto items = scaleBar({20.0f, 150.0f}, std::nanf(""), "?", 1.0f);
  for (const HudItem& item : items) {
    if (const auto* shape = std::get_if<HudShape>(&item)) {
      for (const glm::vec2& p : shape->trianglesPixels) {
        EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
      }
    }
  }
}

}  // namespace
}  // namespace globe::render

namespace globe::render {
namespace {

// Text the font cannot draw (a UTF-8 place name, a control byte) is laid out as one '?' a
// character, never read from before stb's glyph table (UBSan caught that with "Zürich").
TEST(HudText, CharactersTheFontLacksAreQuestionMarks) {
  HudTextBlock utf8;
  utf8.lines = {"Z\xC3\xBCrich, CH", "\xE6\x9D\xB1\xE4\xBA\xAC\t\xFF"};
  HudTextBlock ascii;
  ascii.lines = {"Z?rich, CH", "????"};  // two CJK characters, a tab, a stray byte
  EXPECT_EQ(hudBlockSizePixels(utf8), hudBlockSizePixels(ascii));
  const std::vector<HudTextBlock> blocks{utf8};
  const std::vector<HudTextBlock> same{ascii};
  EXPECT_EQ(buildHudTriangles(blocks).size(), buildHudTriangles(same).size());
}

}  // namespace
}  // namespace globe::render
