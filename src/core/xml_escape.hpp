// Text made safe for XML and HTML element content and double-quoted attributes: one table for
// every writer (TMS documents, saved views, the regression reports); the control characters XML
// cannot hold become U+FFFD.
#pragma once

#include <string>
#include <string_view>

namespace globe {

inline std::string xmlEscaped(std::string_view text) {
  struct Entity {
    char c;
    const char* entity;
  };
  static constexpr Entity kEntities[] = {
      {'&', "&amp;"}, {'<', "&lt;"}, {'>', "&gt;"}, {'"', "&quot;"}, {'\'', "&apos;"}};
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const char* entity = nullptr;
    for (const Entity& e : kEntities) {
      if (e.c == c) entity = e.entity;
    }
    // XML 1.0 has no way to write the other C0 controls (a log's terminal colours), and DEL is
    // discouraged: U+FFFD in their place keeps the document well-formed.
    const auto u = static_cast<unsigned char>(c);
    if (entity == nullptr && ((u < 0x20 && c != '\t' && c != '\n' && c != '\r') || u == 0x7f)) {
      entity = "\xEF\xBF\xBD";
    }
    if (entity != nullptr) {
      out += entity;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace globe
