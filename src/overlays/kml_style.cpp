#include "overlays/kml_style.hpp"

#include <cmath>

#include "overlays/kml_color.hpp"
#include "overlays/xml_elements.hpp"

namespace globe::overlays {
namespace {

constexpr int kMaxStyleMapChain = 8;

void applyColor(const tinyxml2::XMLElement& substyle, Rgba& color) {
  if (auto text = childText(substyle, "color")) {
    if (auto parsed = parseKmlColor(*text)) color = *parsed;
  }
}

void applyNumber(const tinyxml2::XMLElement& substyle, std::string_view name, double& value) {
  if (auto text = childText(substyle, name)) {
    if (auto parsed = parseNumber(*text); parsed && std::isfinite(*parsed) && *parsed >= 0) {
      value = *parsed;
    }
  }
}

void applyBoolean(const tinyxml2::XMLElement& substyle, std::string_view name, bool& value) {
  if (auto text = childText(substyle, name)) {
    if (auto parsed = parseBoolean(*text)) value = *parsed;
  }
}

// One <Style>'s say over `style`: only what it writes changes.
void applyStyle(const tinyxml2::XMLElement& element, Style& style, std::string& iconHref) {
  if (const auto* line = child(element, "LineStyle")) {
    applyColor(*line, style.lineColor);
    applyNumber(*line, "width", style.lineWidthPixels);
  }
  if (const auto* poly = child(element, "PolyStyle")) {
    applyColor(*poly, style.polygonColor);
    applyBoolean(*poly, "fill", style.fill);
    applyBoolean(*poly, "outline", style.outline);
  }
  if (const auto* icon = child(element, "IconStyle")) {
    applyColor(*icon, style.iconColor);
    applyNumber(*icon, "scale", style.iconScale);
    if (const auto* image = child(*icon, "Icon")) iconHref = childText(*image, "href").value_or("");
  }
  if (const auto* label = child(element, "LabelStyle")) {
    applyColor(*label, style.labelColor);
    applyNumber(*label, "scale", style.labelScale);
  }
}

}  // namespace

void KmlStyles::add(const tinyxml2::XMLElement& styleOrMap) {
  const std::string_view name = localName(styleOrMap);
  const char* id = styleOrMap.Attribute("id");
  if ((name == "Style" || name == "StyleMap") && id != nullptr) byId_.emplace(id, &styleOrMap);
}

void KmlStyles::applyUrl(std::string_view styleUrl, Style& style, std::string& iconHref,
                         int depth) const {
  styleUrl = trimmed(styleUrl);
  // Only this document's styles: "#id" (a URL into another file is not fetched).
  if (styleUrl.size() < 2 || styleUrl.front() != '#') return;
  const auto found = byId_.find(styleUrl.substr(1));
  if (found != byId_.end()) applySelector(*found->second, style, iconHref, depth);
}

void KmlStyles::applySelector(const tinyxml2::XMLElement& selector, Style& style,
                              std::string& iconHref, int depth) const {
  if (depth > kMaxStyleMapChain) return;
  if (localName(selector) == "Style") {
    applyStyle(selector, style, iconHref);
    return;
  }
  if (localName(selector) != "StyleMap") return;
  for (const auto* pair = selector.FirstChildElement(); pair; pair = pair->NextSiblingElement()) {
    if (localName(*pair) != "Pair" || childText(*pair, "key").value_or("") != "normal") continue;
    if (auto url = childText(*pair, "styleUrl")) applyUrl(*url, style, iconHref, depth + 1);
    if (const auto* inlineStyle = child(*pair, "Style")) applyStyle(*inlineStyle, style, iconHref);
    return;
  }
}

Style KmlStyles::resolve(std::string_view styleUrl, const tinyxml2::XMLElement* inlineStyle,
                         OverlayImages& images) const {
  Style style;
  std::string iconHref;
  applyUrl(styleUrl, style, iconHref, 0);
  if (inlineStyle != nullptr) applySelector(*inlineStyle, style, iconHref, 0);
  if (!iconHref.empty()) {
    ResolvedImage icon = images.resolve(iconHref);
    style.iconHref = std::move(icon.href);
    style.iconImage = std::move(icon.image);
  }
  return style;
}

}  // namespace globe::overlays
