#include "overlays/kml_color.hpp"

#include <charconv>
#include <cstdint>

#include "overlays/xml_elements.hpp"

namespace globe::overlays {

std::optional<Rgba> parseKmlColor(std::string_view text) {
  text = trimmed(text);
  if (!text.empty() && text.front() == '#') text.remove_prefix(1);
  if (text.size() != 8 && text.size() != 6) return std::nullopt;
  uint32_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value, 16);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if (text.size() == 6) value |= 0xff000000u;
  const auto byte = [value](int shift) { return static_cast<uint8_t>((value >> shift) & 0xffu); };
  return Rgba{byte(0), byte(8), byte(16), byte(24)};
}

}  // namespace globe::overlays
