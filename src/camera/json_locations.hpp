// Where each value of a JSON text starts (its line) and its text as written, by a path such as
// "keyframes[2].lat": nlohmann's DOM keeps no positions, so error messages get them from here.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_map>

namespace globe::camera {

struct JsonLocation {
  int line = 1;               // 1-based line of the value's first character
  size_t begin = 0, end = 0;  // byte range of the value in the text
};

class JsonLocations {
 public:
  // Indexes a text nlohmann has accepted, or read up to a number too large for a double (any text
  // is scanned without crashing or looping); values nested deeper than maxDepth are skipped
  // without recursion (so a hostile nesting depth cannot exhaust the stack).
  explicit JsonLocations(std::string_view text, int maxDepth = 8);

  // The value at path; for an unknown path the nearest indexed ancestor ("keyframes[2]"), else
  // the whole document.
  JsonLocation find(const std::string& path) const;
  int line(const std::string& path) const { return find(path).line; }
  // The path of the first value (in the text's order) written exactly as `written`, or "".
  std::string pathWritten(std::string_view written) const;
  // The value's text as written ("95", "\"cubic\"", "1e999"), at most 40 characters.
  std::string written(const std::string& path) const;

 private:
  std::string_view text_;
  std::unordered_map<std::string, JsonLocation> locations_;
};

// The 1-based line holding byte `offset` of text (offsets past the end: the last line).
int lineOfOffset(std::string_view text, size_t offset);

}  // namespace globe::camera
