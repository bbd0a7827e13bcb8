#include "overlays/xml_elements.hpp"

#include <charconv>

namespace globe::overlays {

std::string_view localName(const tinyxml2::XMLElement& element) {
  std::string_view name = element.Name();
  const size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

const tinyxml2::XMLElement* child(const tinyxml2::XMLElement& parent, std::string_view name) {
  for (const auto* c = parent.FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    if (localName(*c) == name) return c;
  }
  return nullptr;
}

std::string textOf(const tinyxml2::XMLElement& element) {
  std::string text;
  for (const auto* node = element.FirstChild(); node != nullptr; node = node->NextSibling()) {
    if (const auto* t = node->ToText(); t != nullptr && t->Value() != nullptr) text += t->Value();
  }
  return text;
}

std::optional<std::string> childText(const tinyxml2::XMLElement& parent, std::string_view name) {
  const auto* c = child(parent, name);
  if (c == nullptr) return std::nullopt;
  return std::string(trimmed(textOf(*c)));
}

std::string_view trimmed(std::string_view text) {
  constexpr std::string_view kSpace = " \t\r\n\f\v";
  const size_t first = text.find_first_not_of(kSpace);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(kSpace) - first + 1);
}

std::optional<bool> parseBoolean(std::string_view text) {
  text = trimmed(text);
  if (text == "1" || text == "true") return true;
  if (text == "0" || text == "false") return false;
  return std::nullopt;
}

std::optional<double> parseNumber(std::string_view text) {
  text = trimmed(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);  // from_chars refuses '+'
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

Result<const tinyxml2::XMLElement*> parseRootElement(tinyxml2::XMLDocument& xml,
                                                     std::string_view text,
                                                     const std::string& where,
                                                     std::string_view root, std::string_view kind) {
  if (xml.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    return makeError(where + ": not XML (" + std::string(xml.ErrorStr()) + ")");
  }
  const tinyxml2::XMLElement* element = xml.RootElement();
  if (element == nullptr || localName(*element) != root) {
    return makeError(where + ": not " + std::string(kind) + " (the root element is <" +
                     std::string(element != nullptr ? element->Name() : "") + ">, not <" +
                     std::string(root) + ">)");
  }
  return element;
}

}  // namespace globe::overlays
