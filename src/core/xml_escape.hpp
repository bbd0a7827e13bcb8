// Text made safe for XML and HTML element content and double-quoted attributes: one table for
// every writer (TMS documents, saved views, the regression reports).
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
    if (entity != nullptr) {
      out += entity;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace globe
