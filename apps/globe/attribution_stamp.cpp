#include "apps/globe/attribution_stamp.hpp"

#include <algorithm>

namespace globe::app {
namespace {

// The HUD font has ASCII only: the marks attributions use, spelled out; other bytes as '?'.
std::string asciiOf(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      out += static_cast<char>(c);
      continue;
    }
    if (text.compare(i, 2, "\xc2\xa9") == 0) {
      out += "(c)";
    } else if (text.compare(i, 3, "\xe2\x80\x93") == 0 || text.compare(i, 3, "\xe2\x80\x94") == 0) {
      out += "-";
    } else {
      out += '?';
    }
    // Skip the rest of this UTF-8 sequence.
    while (i + 1 < text.size() && (static_cast<unsigned char>(text[i + 1]) & 0xc0) == 0x80) ++i;
  }
  return out;
}

}  // namespace

std::optional<render::HudTextBlock> attributionBlock(const std::vector<std::string>& attributions,
                                                     int widthPixels, int heightPixels) {
  if (attributions.empty()) return std::nullopt;
  render::HudTextBlock block;
  for (const std::string& a : attributions) block.lines.push_back(asciiOf(a));
  block.scale = heightPixels >= 900 ? 1.5f : 1.0f;
  block.paddingPixels = 3.0f;
  block.textRgba = {1.0f, 1.0f, 1.0f, 0.9f};
  block.backgroundRgba = {0.0f, 0.0f, 0.0f, 0.45f};
  const glm::vec2 size = render::hudBlockSizePixels(block);
  block.topLeftPixels = {std::max(0.0f, static_cast<float>(widthPixels) - size.x - 4.0f),
                         std::max(0.0f, static_cast<float>(heightPixels) - size.y - 4.0f)};
  return block;
}

}  // namespace globe::app
