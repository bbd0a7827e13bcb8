// ASCII case folding for file extensions and header keywords (locale-independent, unlike
// std::tolower on a char that may be negative).
#pragma once

#include <cctype>
#include <string>
#include <string_view>

namespace globe::core {

inline std::string asciiLower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

inline std::string asciiUpper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace globe::core
