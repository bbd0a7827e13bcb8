#include "services/url_template.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>

namespace globe::services {

std::string expandTileUrl(const std::string& pattern, const TileUrlValues& values) {
  const uint32_t rows = 1u << values.z;
  std::string out;
  out.reserve(pattern.size() + 16);
  for (size_t i = 0; i < pattern.size();) {
    if (pattern[i] == '{') {
      const size_t close = pattern.find('}', i);
      if (close != std::string::npos) {
        const std::string key = pattern.substr(i + 1, close - i - 1);
        bool known = true;
        if (key == "z") {
          out += std::to_string(values.z);
        } else if (key == "x") {
          out += std::to_string(values.x);
        } else if (key == "y") {
          out += std::to_string(values.y);
        } else if (key == "-y") {
          out += std::to_string(rows - 1 - values.y);
        } else if (key == "version") {
          out += values.version;
        } else if (key == "s" && !values.subdomains.empty()) {
          out += values.subdomains[(values.x + values.y) % values.subdomains.size()];
        } else {
          known = false;
        }
        if (known) {
          i = close + 1;
          continue;
        }
      }
    }
    out += pattern[i++];
  }
  return out;
}

namespace {

// %XX escapes and '+' (a space) in a query value.
std::string percentDecode(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size() && std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(s[i + 2]))) {
      out += static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += s[i] == '+' ? ' ' : s[i];
    }
  }
  return out;
}

}  // namespace

std::string percentEncode(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
      out += static_cast<char>(c);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += hex;
    }
  }
  return out;
}

std::map<std::string, std::string> takeQueryOptions(std::string& url,
                                                    const std::vector<std::string>& keys) {
  std::map<std::string, std::string> taken;
  const size_t question = url.find('?');
  if (question == std::string::npos) return taken;
  std::string kept;
  size_t start = question + 1;
  while (start <= url.size()) {
    size_t end = url.find('&', start);
    if (end == std::string::npos) end = url.size();
    const std::string pair = url.substr(start, end - start);
    const size_t equals = pair.find('=');
    const std::string key = pair.substr(0, equals);
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) {
      taken[key] = equals == std::string::npos ? "" : percentDecode(pair.substr(equals + 1));
    } else if (!pair.empty()) {
      kept += (kept.empty() ? "" : "&") + pair;
    }
    start = end + 1;
  }
  url = url.substr(0, question) + (kept.empty() ? "" : "?" + kept);
  return taken;
}

Result<XyzTemplateOptions> xyzTemplateOptions(const std::string& pattern,
                                              const std::map<std::string, std::string>& options,
                                              uint32_t defaultMaxZoom) {
  if (pattern.find("{z}") == std::string::npos || pattern.find("{x}") == std::string::npos ||
      (pattern.find("{y}") == std::string::npos && pattern.find("{-y}") == std::string::npos)) {
    return makeError("a tile URL template needs {z}, {x} and {y} (or {-y})");
  }
  XyzTemplateOptions out;
  auto maxZoom = optionNumber(options, "maxzoom", defaultMaxZoom, 24);
  if (!maxZoom) return Error{maxZoom.error()};
  auto minZoom = optionNumber(options, "minzoom", 0, *maxZoom);
  if (!minZoom) return Error{minZoom.error()};
  auto tileSize = optionNumber(options, "tilesize", 256, 4096);
  if (!tileSize) return Error{tileSize.error()};
  if (*tileSize != 256 && *tileSize != 512) return makeError("tilesize must be 256 or 512");
  out.minZoom = *minZoom;
  out.maxZoom = *maxZoom;
  out.tileSize = *tileSize;
  const auto s = options.find("subdomains");
  for (char c : s != options.end() ? s->second : std::string("abc"))
    if (c != ',') out.subdomains.emplace_back(1, c);
  return out;
}

Result<uint32_t> optionNumber(const std::map<std::string, std::string>& options,
                              const std::string& key, uint32_t fallback, uint32_t maximum) {
  auto it = options.find(key);
  if (it == options.end()) return fallback;
  uint32_t value = 0;
  const auto [end, ec] =
      std::from_chars(it->second.data(), it->second.data() + it->second.size(), value);
  if (ec != std::errc() || end != it->second.data() + it->second.size() || value > maximum) {
    return makeError(key + "=" + it->second + ": expected a whole number 0.." +
                     std::to_string(maximum));
  }
  return value;
}

}  // namespace globe::services
