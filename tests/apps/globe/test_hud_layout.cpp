// The window's HUD laid out so that no element covers another, at the window sizes people use:
// the status block and the help under it (top left), the compass rose (top right), the scale bar
// (bottom left) and the placemark panel (top right, under the rose).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <variant>
#include <vector>

#include "apps/globe/profile_panel.hpp"
#include "apps/globe/view_session.hpp"
#include "render/hud_renderer.hpp"
#include "render/hud_widgets.hpp"

namespace globe::app {
namespace {

struct Box {
  glm::vec2 low{1e9f}, high{-1e9f};
  void add(glm::vec2 p) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  bool overlaps(const Box& o) const {
    return low.x < o.high.x && o.low.x < high.x && low.y < o.high.y && o.low.y < high.y;
  }
};

Box boxOf(const render::HudItem& item) {
  Box box;
  if (const auto* text = std::get_if<render::HudTextBlock>(&item)) {
    box.add(text->topLeftPixels);
    box.add(text->topLeftPixels + render::hudBlockSizePixels(*text));
  } else {
    for (const glm::vec2& p : std::get<render::HudShape>(item).trianglesPixels) box.add(p);
  }
  return box;
}

TEST(HudLayout, NoElementCoversAnother) {
  // A status block as the window writes it (seven lines, the longest ~70 characters).
  const std::vector<std::string> status = {
      "orbit  lon 138.72740  lat 35.36060  height 6000 m  above ground 2233 m",
      "speed x1  tiles 207 (loading 0)  frame 19 ms",
      "terrain data: E138N35_FUJI.DEM, 3\" (~90 m)",
      "sun 2024-06-21 09:45 UTC  (, . an hour)",
      "layers: 1 on 100%  2 on 100%",
      "lighting auto",
      "H help  K screenshot  V save view  G go to"};
  int sizes = 0;
  for (const auto& [width, height] :
       std::vector<std::pair<int, int>>{{640, 480}, {800, 600}, {1280, 720}, {1920, 1080}}) {
    for (const bool help : {false, true}) {
      std::pair<glm::dvec2, glm::dvec2> compass;
      const auto items = hudItems(status, help, 0.3, 25.0, width, height, compass);
      const size_t blocks = help ? 2 : 1;
      ASSERT_GT(items.size(), blocks);
      Box rose;
      rose.add(glm::vec2(compass.first));
      rose.add(glm::vec2(compass.second));
      Box bar;  // everything after the rose's items
      const size_t roseItems = render::compassRose({0, 0}, 28.0f, 1.0f, 0.3).size();
      for (size_t k = blocks + roseItems; k < items.size(); ++k) {
        const Box part = boxOf(items[k]);
        bar.add(part.low);
        bar.add(part.high);
      }
      // The placemark panel where the view puts it, as wide as it may be, 120 pixels tall.
      const PlacemarkPanelPlace place = placemarkPanelPlace(items, blocks, compass, width);
      const float panelWidth =
          std::min({place.maxWidthPixels, 420.0f, 0.4f * static_cast<float>(width)});
      EXPECT_GE(panelWidth, std::min(kMinimumPanelWidth, 0.4f * static_cast<float>(width)));
      Box panel;
      panel.add({static_cast<float>(width) - panelWidth - 12.0f, place.topPixels});
      panel.add({static_cast<float>(width) - 12.0f, place.topPixels + 120.0f});
      const std::string where = std::to_string(width) + "x" + std::to_string(height) +
                                (help ? " with help" : "");
      for (size_t b = 0; b < blocks; ++b) {
        const Box block = boxOf(items[b]);
        EXPECT_FALSE(block.overlaps(rose)) << "text block " << b << " and the rose, " << where;
        EXPECT_FALSE(block.overlaps(bar)) << "text block " << b << " and the scale bar, " << where;
        EXPECT_FALSE(block.overlaps(panel)) << "text block " << b << " and the panel, " << where;
        EXPECT_LE(block.high.y, static_cast<float>(height)) << "text block " << b << ", " << where;
      }
      EXPECT_FALSE(rose.overlaps(panel)) << where;
      EXPECT_FALSE(rose.overlaps(bar)) << where;
      ++sizes;
    }
  }
  EXPECT_EQ(sizes, 8);
}

// The elevation profile chart goes to the bottom corner that hides less of the path it profiles:
// a ruler drawn in the bottom left moves it right; one on the right, or none, leaves it left.
TEST(HudLayout, TheProfileChartDoesNotHideThePathItProfiles) {
  const int width = 1280, height = 720;
  const float margin = 34.0f;
  const glm::ivec2 chart = profileChartSizePixels(width, height);
  const auto line = [](glm::dvec2 from, glm::dvec2 to) {
    std::vector<glm::dvec2> points;
    for (int i = 0; i <= 100; ++i) points.push_back(from + (to - from) * (i / 100.0));
    return points;
  };
  const auto bottomLeft = line({60, 650}, {400, 500});
  const auto bottomRight = line({900, 650}, {1200, 520});
  const auto top = line({100, 80}, {1100, 120});
  EXPECT_EQ(profileChartCorner(bottomLeft, chart, width, height, margin), ChartCorner::BottomRight);
  EXPECT_EQ(profileChartCorner(bottomRight, chart, width, height, margin), ChartCorner::BottomLeft);
  EXPECT_EQ(profileChartCorner(top, chart, width, height, margin), ChartCorner::BottomLeft);
  EXPECT_EQ(profileChartCorner({}, chart, width, height, margin), ChartCorner::BottomLeft);
  // Across the whole bottom: the corner with fewer of its points.
  auto across = line({20, 600}, {1260, 600});
  const auto more = line({700, 640}, {1250, 560});
  across.insert(across.end(), more.begin(), more.end());
  EXPECT_EQ(profileChartCorner(across, chart, width, height, margin), ChartCorner::BottomLeft);
  // The corners sit inside the frame, above the margin, clear of each other.
  for (const ChartCorner corner : {ChartCorner::BottomLeft, ChartCorner::BottomRight}) {
    const glm::vec2 topLeft = profileChartTopLeft(corner, chart, width, height, margin);
    EXPECT_GE(topLeft.x, 0.0f);
    EXPECT_LE(topLeft.x + static_cast<float>(chart.x), static_cast<float>(width));
    EXPECT_NEAR(topLeft.y + static_cast<float>(chart.y), height - margin, 1.0f);
  }
}

}  // namespace
}  // namespace globe::app
