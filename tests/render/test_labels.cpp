// Labels with FreeType + HarfBuzz: shaping and measuring without GL (scripts, direction, bad
// UTF-8), decluttering and word wrapping on the CPU, then real drawing into an OSMesa framebuffer
// read back: bright text with a dark halo inside the placed box and nothing outside, tinted icons.
// The frame of TheTestFrameIsWrittenAsAPng is labels.png next to the test binary, to look at.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "text/font_face.hpp"
#include "render/gl.hpp"
#include "render/glyph_atlas.hpp"
#include "text/label_layout.hpp"
#include "render/label_renderer.hpp"
#include "render/osmesa_context.hpp"
#include "render/pin_icon.hpp"
#include "text/text_wrap.hpp"
#include "tests/render/render_test_support.hpp"

namespace globe::render {
namespace label_test {

const char* const kZurich = "Z\xC3\xBCrich";
const char* const kMoscow = "\xD0\x9C\xD0\xBE\xD1\x81\xD0\xBA\xD0\xB2\xD0\xB0";
const char* const kTokyo = "\xE6\x9D\xB1\xE4\xBA\xAC";
const char* const kAthens = "\xCE\x91\xCE\xB8\xCE\xAE\xCE\xBD\xCE\xB1";   // Αθήνα
const char* const kMarhaba = "\xD9\x85\xD8\xB1\xD8\xAD\xD8\xA8\xD8\xA7";  // مرحبا
const char* const kShalom = "\xD7\xA9\xD7\x9C\xD7\x95\xD7\x9D";           // שלום

std::unique_ptr<text::FontFace> loadFont() {
  auto font = text::FontFace::loadDefault();
  EXPECT_TRUE(font) << (font ? "" : font.error());
  return font ? std::move(*font) : nullptr;
}

TEST(FontFace, GlobeFontOverridesTheDefaultAndAMissingOneIsNamed) {
  ASSERT_TRUE(text::findLabelFont()) << text::findLabelFont().error();
  setenv("GLOBE_FONT", "/nonexistent/font.ttf", 1);
  const auto missing = text::findLabelFont();
  setenv("GLOBE_FONT", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", 1);
  const auto chosen = text::findLabelFont();
  unsetenv("GLOBE_FONT");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("/nonexistent/font.ttf"), std::string::npos);
  ASSERT_TRUE(chosen);
  EXPECT_EQ(chosen->filename(), "DejaVuSans.ttf");
  EXPECT_FALSE(text::FontFace::load("/nonexistent/font.ttf"));
}

TEST(FontFace, MeasuredWidthGrowsWithTextLengthAndSize) {
  auto font = loadFont();
  ASSERT_TRUE(font);
  const text::TextExtent shortText = font->measure("Zu", 16.0f);
  const text::TextExtent longText = font->measure(kZurich, 16.0f);
  const text::TextExtent larger = font->measure(kZurich, 32.0f);
  EXPECT_GT(shortText.widthPixels, 5.0f);
  EXPECT_GT(longText.widthPixels, shortText.widthPixels + 10.0f);
  EXPECT_NEAR(larger.widthPixels, 2.0f * longText.widthPixels, 0.05f * larger.widthPixels);
  EXPECT_GT(longText.ascentPixels, 10.0f);
  EXPECT_LT(longText.ascentPixels, 20.0f);
  EXPECT_GT(longText.descentPixels, 2.0f);
  EXPECT_EQ(font->measure("", 16.0f).widthPixels, 0.0f);
  EXPECT_EQ(font->measure(kZurich, std::nanf("")).widthPixels, 0.0f);
  EXPECT_EQ(font->measure(kZurich, -3.0f).widthPixels, 0.0f);
}

TEST(FontFace, LatinCyrillicAndGreekHaveGlyphsAndCjkIsTheNotdefBox) {
  auto font = loadFont();
  ASSERT_TRUE(font);
  for (const char* text : {kZurich, kMoscow, kAthens}) {
    const text::ShapedText shaped = font->shape(text, 20.0f);
    EXPECT_FALSE(shaped.rightToLeft) << text;
    ASSERT_FALSE(shaped.glyphs.empty()) << text;
    for (const text::ShapedGlyph& glyph : shaped.glyphs) EXPECT_NE(glyph.glyphId, 0u) << text;
    // Left to right: the pen only moves right.
    for (size_t i = 1; i < shaped.glyphs.size(); ++i) {
      EXPECT_GT(shaped.glyphs[i].originPixels.x, shaped.glyphs[i - 1].originPixels.x) << text;
    }
  }
  // DejaVu has no CJK: each character is glyph 0, the font's .notdef (a hollow box), which is
  // drawn like any glyph, so the label shows two boxes rather than nothing or garbage.
  const text::ShapedText tokyo = font->shape(kTokyo, 20.0f);
  ASSERT_EQ(tokyo.glyphs.size(), 2u);
  for (const text::ShapedGlyph& glyph : tokyo.glyphs) EXPECT_EQ(glyph.glyphId, 0u);
  EXPECT_GT(tokyo.extent.widthPixels, 10.0f);
  const text::GlyphBitmap box = font->rasterize(0, 20.0f, 2.0f);
  EXPECT_GT(box.widthPixels, 4);
  EXPECT_GT(box.heightPixels, 8);
}

TEST(FontFace, ArabicAndHebrewAreShapedRightToLeft) {
  auto font = loadFont();
  ASSERT_TRUE(font);
  for (const char* text : {kMarhaba, kShalom}) {
    const text::ShapedText shaped = font->shape(text, 20.0f);
    EXPECT_TRUE(shaped.rightToLeft) << text;
    ASSERT_GE(shaped.glyphs.size(), 4u) << text;
    // Visual order: the first character (cluster 0) is the rightmost glyph.
    EXPECT_EQ(shaped.glyphs.back().clusterByte, 0u) << text;
    for (size_t i = 1; i < shaped.glyphs.size(); ++i) {
      EXPECT_LE(shaped.glyphs[i].clusterByte, shaped.glyphs[i - 1].clusterByte) << text;
    }
    for (const text::ShapedGlyph& glyph : shaped.glyphs) EXPECT_NE(glyph.glyphId, 0u) << text;
  }
  // Joining: beh alone is its isolated form; in the middle of three it is the medial form.
  const text::ShapedText alone = font->shape("\xD8\xA8", 20.0f);
  const text::ShapedText three = font->shape("\xD8\xA8\xD8\xA8\xD8\xA8", 20.0f);
  ASSERT_EQ(alone.glyphs.size(), 1u);
  ASSERT_EQ(three.glyphs.size(), 3u);
  EXPECT_NE(three.glyphs[1].glyphId, alone.glyphs[0].glyphId);
}

TEST(FontFace, InvalidUtf8IsReplacedNotACrash) {
  auto font = loadFont();
  ASSERT_TRUE(font);
  const std::string bad = "a\xFF\xFE b\xC3";  // stray bytes and a truncated sequence
  const text::ShapedText shaped = font->shape(bad, 16.0f);
  EXPECT_GE(shaped.glyphs.size(), 4u);
  EXPECT_GT(shaped.extent.widthPixels, 0.0f);
  for (const text::ShapedGlyph& glyph : shaped.glyphs) {
    EXPECT_LE(glyph.clusterByte, bad.size());
    (void)font->rasterize(glyph.glyphId, 16.0f, 2.0f);
  }
  (void)font->rasterize(0xFFFFFFu, 16.0f, 2.0f);  // no such glyph: empty, not a crash
}

TEST(FontFace, TheHaloCoversTheGlyphAndGrowsItByItsRadius) {
  auto font = loadFont();
  ASSERT_TRUE(font);
  const text::ShapedText shaped = font->shape("O", 24.0f);
  ASSERT_EQ(shaped.glyphs.size(), 1u);
  const text::GlyphBitmap plain = font->rasterize(shaped.glyphs[0].glyphId, 24.0f, 0.0f);
  const text::GlyphBitmap haloed = font->rasterize(shaped.glyphs[0].glyphId, 24.0f, 3.0f);
  EXPECT_GE(haloed.widthPixels, plain.widthPixels + 5);
  EXPECT_GE(haloed.heightPixels, plain.heightPixels + 5);
  int fill = 0, halo = 0;
  for (size_t i = 0; i < haloed.fillAndHalo.size(); i += 2) {
    EXPECT_GE(haloed.fillAndHalo[i + 1], haloed.fillAndHalo[i]);
    fill += haloed.fillAndHalo[i] > 128 ? 1 : 0;
    halo += haloed.fillAndHalo[i + 1] > 128 ? 1 : 0;
  }
  EXPECT_GT(fill, 50);
  EXPECT_GT(halo, 2 * fill);
}

TEST(ShelfPacker, PacksWithoutOverlapUntilFull) {
  ShelfPacker packer(64);
  std::vector<std::pair<glm::ivec2, glm::ivec2>> boxes;
  for (int i = 0; i < 100; ++i) {
    const glm::ivec2 size(5 + i % 7, 6 + i % 5);
    const auto at = packer.insert(size);
    if (!at) break;
    EXPECT_LE(at->x + size.x, 64);
    EXPECT_LE(at->y + size.y, 64);
    for (const auto& [otherAt, otherSize] : boxes) {
      const bool apart = at->x >= otherAt.x + otherSize.x || otherAt.x >= at->x + size.x ||
                         at->y >= otherAt.y + otherSize.y || otherAt.y >= at->y + size.y;
      EXPECT_TRUE(apart);
    }
    boxes.emplace_back(*at, size);
  }
  EXPECT_GT(boxes.size(), 30u);
  EXPECT_LT(boxes.size(), 100u);
  EXPECT_FALSE(packer.insert({65, 1}));
  packer.grow(128);
  EXPECT_TRUE(packer.insert({100, 10}));
}

// 10 pixels a byte, ascent 12, descent 4: layout without a font.
text::TextExtent fakeMeasure(const std::string& text, float) {
  return {10.0f * static_cast<float>(text.size()), 12.0f, 4.0f};
}

text::ScreenLabel labelAt(std::string text, double x, double y) {
  text::ScreenLabel label;
  label.text = std::move(text);
  label.anchorPixels = {x, y};
  return label;
}

TEST(LabelLayout, DropsTheLaterOfTwoOverlappingLabelsAndOffScreenOnes) {
  std::vector<text::ScreenLabel> labels{
      labelAt("first", 100, 100),                               // 50 wide
      labelAt("second", 120, 105),                              // overlaps the first: dropped
      labelAt("third", 100, 200),                               // clear of both
      labelAt("gone", -500, 100),                               // wholly left of the screen
      labelAt("edge", 390, 50),                                 // partly on screen: kept
      labelAt("nan", std::nan(""), 10), labelAt("", 300, 300),  // nothing to draw
  };
  const std::vector<text::PlacedLabel> placed = text::layoutLabels(labels, {400, 300}, fakeMeasure);
  std::vector<size_t> indices;
  for (const text::PlacedLabel& p : placed) indices.push_back(p.index);
  EXPECT_EQ(indices, (std::vector<size_t>{0, 2, 4}));
  const text::PlacedLabel& first = placed[0];
  // The text starts at the anchor (plus the halo) and is centred on it vertically.
  EXPECT_NEAR(first.minPixels.x, 100.0f, 0.01f);
  EXPECT_NEAR(first.maxPixels.x, 100.0f + 50.0f + 2 * std::ceil(text::labelHaloPixels(16.0f)), 0.01f);
  EXPECT_LT(first.minPixels.y, 92.0f);
  EXPECT_GT(first.maxPixels.y, 104.0f);
  EXPECT_TRUE(first.withText);
}

TEST(LabelLayout, AnIconAloneIsKeptWhenOnlyItsTextCollides) {
  std::vector<text::ScreenLabel> labels{labelAt("wide text here", 100, 100), labelAt("blocked", 60, 100)};
  labels[1].iconKey = "pin";
  labels[1].iconSizePixels = 16;  // icon 52..68, text from ~75 runs into the first label
  const std::vector<text::PlacedLabel> placed = text::layoutLabels(labels, {400, 300}, fakeMeasure);
  ASSERT_EQ(placed.size(), 2u);
  EXPECT_EQ(placed[1].index, 1u);
  EXPECT_FALSE(placed[1].withText);
  EXPECT_EQ(placed[1].minPixels, glm::vec2(52, 92));
  EXPECT_EQ(placed[1].maxPixels, glm::vec2(68, 108));
  // With its icon in the way too, the whole label goes.
  labels[1].anchorPixels = {110, 100};
  EXPECT_EQ(text::layoutLabels(labels, {400, 300}, fakeMeasure).size(), 1u);
}

TEST(TextWrap, BreaksAtSpacesWithinTheWidth) {
  const auto width = [](std::string_view text) { return 8.0f * static_cast<float>(text.size()); };
  const std::vector<std::string> lines =
      text::wrapText("the quick brown fox jumps over the lazy dog", 80.0f, width);
  EXPECT_EQ(lines,
            (std::vector<std::string>{"the quick", "brown fox", "jumps over", "the lazy", "dog"}));
  for (const std::string& line : lines) EXPECT_LE(width(line), 80.0f);
  // A word wider than a line is cut between characters, never inside a UTF-8 sequence.
  const std::vector<std::string> cut =
      text::wrapText("ab \xC3\xBC\xC3\xBC\xC3\xBC\xC3\xBC", 33.0f, width);
  EXPECT_EQ(cut, (std::vector<std::string>{"ab", "\xC3\xBC\xC3\xBC", "\xC3\xBC\xC3\xBC"}));
  EXPECT_EQ(text::wrapText("one\ntwo three", 1000.0f, width),
            (std::vector<std::string>{"one", "two three"}));
  EXPECT_EQ(text::wrapText("", 80.0f, width), (std::vector<std::string>{""}));
}

// Rendering -----------------------------------------------------------------------------------

constexpr int kFrameWidth = 480;
constexpr int kFrameHeight = 320;
constexpr float kGrey = 0.5f;

struct LabelFrame {
  std::unique_ptr<OsMesaContext> context;
  std::unique_ptr<LabelRenderer> labels;
};

LabelFrame makeFrame() {
  LabelFrame frame;
  auto context = OsMesaContext::create(kFrameWidth, kFrameHeight);
  EXPECT_TRUE(context) << (context ? "" : context.error());
  if (!context) return frame;
  frame.context = std::move(*context);
  auto labels = LabelRenderer::create({});
  EXPECT_TRUE(labels) << (labels ? "" : labels.error());
  if (labels) frame.labels = std::move(*labels);
  glClearColor(kGrey, kGrey, kGrey, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  return frame;
}

bool insideAny(const std::vector<text::PlacedLabel>& placed, int x, int y) {
  return std::any_of(placed.begin(), placed.end(), [&](const text::PlacedLabel& p) {
    const glm::vec2 centre(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
    return centre.x > p.minPixels.x && centre.x < p.maxPixels.x && centre.y > p.minPixels.y &&
           centre.y < p.maxPixels.y;
  });
}

TEST(LabelRenderer, TextIsBrightWithADarkHaloInsideItsBoxAndNothingOutside) {
  LabelFrame frame = makeFrame();
  ASSERT_TRUE(frame.labels);
  std::vector<text::ScreenLabel> labels{labelAt(kZurich, 40, 60), labelAt(kMoscow, 40, 140),
                                  labelAt(kMarhaba, 260, 60), labelAt(kTokyo, 260, 140)};
  for (text::ScreenLabel& label : labels) label.sizePixels = 24.0f;
  const std::vector<text::PlacedLabel> placed = frame.labels->layout(labels, {kFrameWidth, kFrameHeight});
  ASSERT_EQ(placed.size(), labels.size());
  frame.labels->draw(labels, placed, {kFrameWidth, kFrameHeight});
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // HudRenderer's contract: depth test and culling back on, blending off.
  EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
  EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
  EXPECT_FALSE(glIsEnabled(GL_BLEND));
  const test::Image image = test::readImage(kFrameWidth, kFrameHeight);
  test::savePng(image, "labels_text");
  const int grey = static_cast<int>(std::lround(kGrey * 255));
  int outside = 0;
  for (int y = 0; y < kFrameHeight; ++y) {
    for (int x = 0; x < kFrameWidth; ++x) {
      if (insideAny(placed, x, y)) continue;
      const auto p = image.at(x, y);
      if (std::abs(p[0] - grey) > 1 || std::abs(p[1] - grey) > 1 || std::abs(p[2] - grey) > 1) {
        ++outside;
      }
    }
  }
  EXPECT_EQ(outside, 0);
  for (const text::PlacedLabel& p : placed) {
    int bright = 0, dark = 0;
    for (int y = static_cast<int>(p.minPixels.y); y < static_cast<int>(p.maxPixels.y); ++y) {
      for (int x = static_cast<int>(p.minPixels.x); x < static_cast<int>(p.maxPixels.x); ++x) {
        const double luminance = image.luminance(x, y);
        bright += luminance > 230 ? 1 : 0;
        dark += luminance < 60 ? 1 : 0;
      }
    }
    EXPECT_GT(bright, 40) << labels[p.index].text;
    EXPECT_GT(dark, 40) << labels[p.index].text;
  }
}

TEST(LabelRenderer, IconColoursAreMultipliedByIconRgba) {
  LabelFrame frame = makeFrame();
  ASSERT_TRUE(frame.labels);
  EXPECT_TRUE(frame.labels->hasIcon("pin"));
  formats::ImageRgba white{8, 8, std::vector<uint8_t>(8 * 8 * 4, 255)};
  frame.labels->setIcon("square", white);
  EXPECT_TRUE(frame.labels->hasIcon("square"));
  frame.labels->setIcon("broken", formats::ImageRgba{8, 8, {1, 2, 3}});
  EXPECT_FALSE(frame.labels->hasIcon("broken"));
  std::vector<text::ScreenLabel> labels{labelAt("", 100, 100), labelAt("", 300, 100),
                                  labelAt("", 200, 250)};
  labels[0].iconKey = "square";
  labels[0].iconRgba = {1.0f, 0.5f, 0.0f, 1.0f};
  labels[1].iconKey = "pin";
  labels[1].iconRgba = {1.0f, 1.0f, 0.0f, 1.0f};  // a yellow pin
  labels[2].iconKey = "no such icon";             // placed, draws nothing
  for (text::ScreenLabel& label : labels) label.iconSizePixels = 40.0f;
  const std::vector<text::PlacedLabel> placed = frame.labels->layout(labels, {kFrameWidth, kFrameHeight});
  ASSERT_EQ(placed.size(), 3u);
  frame.labels->draw(labels, placed, {kFrameWidth, kFrameHeight});
  const test::Image image = test::readImage(kFrameWidth, kFrameHeight);
  const auto square = image.at(100, 100);
  EXPECT_NEAR(square[0], 255, 2);
  EXPECT_NEAR(square[1], 128, 2);
  EXPECT_NEAR(square[2], 0, 2);
  const auto pin = image.at(300, 100);
  EXPECT_GT(pin[0], 240);
  EXPECT_GT(pin[1], 240);
  EXPECT_LT(pin[2], 15);
  const auto rim = image.at(300 + 17, 100);  // the dark rim, 3 px inside the edge
  EXPECT_LT(rim[0], 80);
  const auto corner = image.at(300 + 19, 100 + 19);  // outside the disc: the background
  EXPECT_NEAR(corner[0], 128, 1);
  const auto missing = image.at(200, 250);
  EXPECT_NEAR(missing[0], 128, 1);
}

TEST(LabelRenderer, TheTextPanelIsADarkBoxHoldingWrappedText) {
  LabelFrame frame = makeFrame();
  ASSERT_TRUE(frame.labels);
  const std::vector<std::string> paragraphs{
      kZurich, "Largest city of Switzerland, on Lake Zurich, at the foot of the Alps."};
  const glm::vec2 size = frame.labels->textPanelSizePixels(paragraphs, 200.0f);
  EXPECT_LE(size.x, 200.0f);
  EXPECT_GT(size.y, 4 * 14.0f);  // the description needs several lines at 200 pixels
  frame.labels->drawTextPanel(paragraphs, {20.0f, 30.0f}, 200.0f, {kFrameWidth, kFrameHeight});
  const test::Image image = test::readImage(kFrameWidth, kFrameHeight);
  int bright = 0, changedOutside = 0;
  for (int y = 0; y < kFrameHeight; ++y) {
    for (int x = 0; x < kFrameWidth; ++x) {
      const bool inside = x >= 20 && static_cast<float>(x) < 20 + size.x && y >= 30 &&
                          static_cast<float>(y) < 30 + size.y;
      if (!inside) {
        changedOutside += std::abs(image.at(x, y)[0] - 128) > 1 ? 1 : 0;
      } else {
        bright += image.luminance(x, y) > 230 ? 1 : 0;
      }
    }
  }
  EXPECT_EQ(changedOutside, 0);
  EXPECT_GT(bright, 200);
  EXPECT_LT(image.luminance(22, 32), 60);  // the box's padding: dark
}

TEST(LabelRenderer, TheTestFrameIsWrittenAsAPng) {
  LabelFrame frame = makeFrame();
  ASSERT_TRUE(frame.labels);
  // A checkerboard of light and dark "imagery", so the halo shows over both.
  glEnable(GL_SCISSOR_TEST);
  for (int y = 0; y < kFrameHeight; y += 40) {
    for (int x = 0; x < kFrameWidth; x += 40) {
      const float v = ((x + y) / 40) % 2 == 0 ? 0.85f : 0.3f;
      glScissor(x, y, 40, 40);
      glClearColor(v, v * 0.9f, v * 0.7f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
    }
  }
  glDisable(GL_SCISSOR_TEST);
  std::vector<text::ScreenLabel> labels{labelAt(kZurich, 30, 30),          labelAt(kMoscow, 30, 70),
                                  labelAt(kAthens, 30, 110),         labelAt(kMarhaba, 30, 150),
                                  labelAt(kShalom, 30, 190),         labelAt(kTokyo, 30, 230),
                                  labelAt("Overlaps", 50, 35),  // dropped
                                  labelAt("Big Label 32px", 30, 280)};
  for (size_t i = 0; i < 6; ++i) {
    labels[i].iconKey = "pin";
    labels[i].iconSizePixels = 20.0f;
    labels[i].iconRgba = {1.0f, 0.85f - 0.1f * static_cast<float>(i), 0.2f, 1.0f};
  }
  labels[2].sizePixels = 20.0f;
  labels[7].sizePixels = 32.0f;
  labels[7].textRgba = {1.0f, 1.0f, 0.4f, 1.0f};
  const std::vector<text::PlacedLabel> placed = frame.labels->layout(labels, {kFrameWidth, kFrameHeight});
  EXPECT_EQ(placed.size(), 7u);
  frame.labels->draw(labels, placed, {kFrameWidth, kFrameHeight});
  frame.labels->drawTextPanel(
      {"Z\xC3\xBCrich",
       "Largest city of Switzerland, on Lake Z\xC3\xBCrich. "
       "\xD0\x9C\xD0\xBE\xD1\x81\xD0\xBA\xD0\xB2\xD0\xB0 and \xCE\x91\xCE\xB8"
       "\xCE\xAE\xCE\xBD\xCE\xB1 wrap too."},
      {250.0f, 20.0f}, 210.0f, {kFrameWidth, kFrameHeight});
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const test::Image image = test::readImage(kFrameWidth, kFrameHeight);
  test::savePng(image, "labels");
  EXPECT_TRUE(std::filesystem::exists(test::outputDirectory() / "labels.png"));
}

}  // namespace label_test
}  // namespace globe::render
