// A small scanner over already-valid JSON recording each value's line and byte range by path.
#include "camera/json_locations.hpp"

#include <algorithm>

namespace globe::camera {
namespace {

class Scanner {
 public:
  Scanner(std::string_view text, int maxDepth, std::unordered_map<std::string, JsonLocation>& out)
      : s_(text), maxDepth_(maxDepth), out_(out) {
    if (s_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3;  // a UTF-8 byte order mark
  }

  void value(const std::string& path, int depth) {
    whitespace();
    if (i_ >= s_.size()) return;
    JsonLocation location{line_, i_, i_};
    const char c = s_[i_];
    if (depth >= maxDepth_ && (c == '{' || c == '[')) {
      skipNested();
    } else if (c == '{') {
      ++i_;
      for (;;) {
        whitespace();
        if (i_ >= s_.size() || s_[i_] == '}') break;
        const std::string key = string();
        whitespace();
        ++i_;  // ':'
        const size_t before = i_;
        value(path.empty() ? key : path + "." + key, depth + 1);
        whitespace();
        if (i_ < s_.size() && (s_[i_] == ',' || i_ == before)) ++i_;
      }
      ++i_;
    } else if (c == '[') {
      ++i_;
      for (size_t index = 0;; ++index) {
        whitespace();
        if (i_ >= s_.size() || s_[i_] == ']') break;
        const size_t before = i_;
        value(path + "[" + std::to_string(index) + "]", depth + 1);
        whitespace();
        // A stray character (only in a text nlohmann stopped reading early) is stepped over.
        if (i_ < s_.size() && (s_[i_] == ',' || i_ == before)) ++i_;
      }
      ++i_;
    } else if (c == '"') {
      string();
    } else {
      while (i_ < s_.size() &&
             std::string_view(",]} \t\r\n").find(s_[i_]) == std::string_view::npos) {
        ++i_;
      }
    }
    location.end = std::min(i_, s_.size());
    out_[path] = location;  // a repeated key: the last one wins, as in nlohmann's DOM
  }

 private:
  void whitespace() {
    while (i_ < s_.size() &&
           (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r')) {
      if (s_[i_] == '\n') ++line_;
      ++i_;
    }
  }
  // The raw characters between the quotes (escapes kept as written).
  std::string string() {
    const size_t start = ++i_;
    while (i_ < s_.size() && s_[i_] != '"') i_ += s_[i_] == '\\' ? 2 : 1;
    const std::string raw(s_.substr(start, std::min(i_, s_.size()) - start));
    ++i_;
    return raw;
  }
  void skipNested() {
    size_t depth = 0;
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '"') {
        string();
        continue;
      }
      if (c == '\n') ++line_;
      ++i_;
      if (c == '{' || c == '[') ++depth;
      if ((c == '}' || c == ']') && --depth == 0) return;
    }
  }

  std::string_view s_;
  int maxDepth_;
  std::unordered_map<std::string, JsonLocation>& out_;
  size_t i_ = 0;
  int line_ = 1;
};

}  // namespace

JsonLocations::JsonLocations(std::string_view text, int maxDepth) : text_(text) {
  Scanner(text, maxDepth, locations_).value("", 0);
}

JsonLocation JsonLocations::find(const std::string& path) const {
  std::string at = path;
  for (;;) {
    if (auto it = locations_.find(at); it != locations_.end()) return it->second;
    const size_t cut = at.find_last_of(".[");
    if (cut == std::string::npos) break;
    at.resize(cut);
  }
  auto root = locations_.find("");
  return root != locations_.end() ? root->second : JsonLocation{};
}

std::string JsonLocations::written(const std::string& path) const {
  const JsonLocation location = find(path);
  std::string text(text_.substr(location.begin, location.end - location.begin));
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return text;
}

std::string JsonLocations::pathWritten(std::string_view written) const {
  std::string best;
  size_t bestBegin = text_.size();
  for (const auto& [path, location] : locations_) {
    if (location.begin <= bestBegin &&
        text_.substr(location.begin, location.end - location.begin) == written) {
      if (location.begin < bestBegin || path < best) best = path;
      bestBegin = location.begin;
    }
  }
  return best;
}

int lineOfOffset(std::string_view text, size_t offset) {
  const size_t end = std::min(offset, text.size());
  return 1 +
         static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(end), '\n'));
}

}  // namespace globe::camera
