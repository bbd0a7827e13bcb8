// Tile URL templates as services publish them: {z} {x} {y}, {-y} for TMS rows (from the south),
// {s} a subdomain, {version}; and a service argument's own options, given as query keys after
// the URL (?maxzoom=15) and taken out of it before it is requested.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::services {

struct TileUrlValues {
  uint32_t z = 0, x = 0, y = 0;  // y: the row from the north (XYZ)
  std::string version;
  std::vector<std::string> subdomains;  // {s}: picked by the tile, so a tile's URL never changes
};

std::string expandTileUrl(const std::string& pattern, const TileUrlValues& values);

// Removes `keys` from the URL's query and returns them, percent-decoded; other query keys (an
// API key) stay. Every service takes `attribution` (who the data is from, shown with it).
std::map<std::string, std::string> takeQueryOptions(std::string& url,
                                                    const std::vector<std::string>& keys);

// What every {z}/{x}/{y} template takes: minzoom, maxzoom (defaultMaxZoom unless given, at most
// 24), tilesize (256 or 512) and subdomains (letters for {s}, default "abc").
struct XyzTemplateOptions {
  uint32_t minZoom = 0, maxZoom = 0, tileSize = 256;
  std::vector<std::string> subdomains;
};
// Errors: a template without {z}, {x} and {y} (or {-y}), an option out of range.
Result<XyzTemplateOptions> xyzTemplateOptions(const std::string& pattern,
                                              const std::map<std::string, std::string>& options,
                                              uint32_t defaultMaxZoom);

// RFC 3986's unreserved characters as they are, every other byte as %XX.
std::string percentEncode(const std::string& s);

// An option as a non-negative integer no larger than `maximum`; errors name the option.
Result<uint32_t> optionNumber(const std::map<std::string, std::string>& options,
                              const std::string& key, uint32_t fallback, uint32_t maximum);

}  // namespace globe::services
