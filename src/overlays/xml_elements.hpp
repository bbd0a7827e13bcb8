// Small tinyxml2 helpers the KML and GPX readers share: elements by local name (KML and GPX
// files use prefixes and several namespaces), their text, KML booleans and numbers.
#pragma once

#include <tinyxml2.h>

#include <optional>
#include <string>
#include <string_view>

#include "core/result.hpp"

namespace globe::overlays {

// The element's name without a namespace prefix: "gx:Track" is "Track".
std::string_view localName(const tinyxml2::XMLElement& element);

// The first child element with this local name, or nullptr.
const tinyxml2::XMLElement* child(const tinyxml2::XMLElement& parent, std::string_view name);

// All the element's text and CDATA children joined, as written (no trimming).
std::string textOf(const tinyxml2::XMLElement& element);

// The text of the first child with this local name, trimmed; nullopt without that child.
std::optional<std::string> childText(const tinyxml2::XMLElement& parent, std::string_view name);

std::string_view trimmed(std::string_view text);

// Parses `text` into `xml` and returns its root element, which must have the local name `root`;
// errors name `where` and say "not XML (why)" or "not KIND (the root element is <x>, not <root>)".
Result<const tinyxml2::XMLElement*> parseRootElement(tinyxml2::XMLDocument& xml,
                                                     std::string_view text,
                                                     const std::string& where,
                                                     std::string_view root, std::string_view kind);

// KML's xsd:boolean: "1"/"true" or "0"/"false"; nullopt for anything else.
std::optional<bool> parseBoolean(std::string_view text);

// A whole (trimmed) decimal number, locale-independent; nullopt when the text is not one.
std::optional<double> parseNumber(std::string_view text);

}  // namespace globe::overlays
