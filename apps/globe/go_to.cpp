#include "apps/globe/go_to.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "camera/path_checks.hpp"

namespace globe::app {
namespace {

// Approximate coordinates (4 decimals) of summits, parks and town centres from public gazetteers
// (GNIS, GSI Japan, Ordnance Survey); a go-to lands ~15 km from the point, looking at it.
constexpr Place kPlaces[] = {
    {"Mount Fuji", 35.3606, 138.7274},
    {"Fujinomiya", 35.2221, 138.6211},
    {"Gotemba", 35.3087, 138.9347},
    {"Numazu", 35.0956, 138.8634},
    {"Lake Kawaguchi", 35.5167, 138.7500},
    {"Suruga Bay", 34.9000, 138.6000},
    {"Zion National Park", 37.2982, -113.0263},
    {"Angels Landing", 37.2692, -112.9480},
    {"The Watchman", 37.1961, -112.9688},
    {"Springdale", 37.1889, -112.9986},
    {"Kolob Canyons", 37.4536, -113.2250},
    {"Lincoln", 53.2307, -0.5406},
    {"Nottingham", 52.9548, -1.1581},
    {"Boston, Lincolnshire", 52.9789, -0.0266},
    {"The Wash", 52.9333, 0.3000},
    {"Mount Everest", 27.9881, 86.9250},
    {"Tokyo", 35.6812, 139.7671},
    {"London", 51.5074, -0.1278},
    {"Grand Canyon", 36.1069, -112.1129},
    {"Kilimanjaro", -3.0674, 37.3556},
};

// Lower case letters and digits only: "Angels Landing" and "angelslanding" are the same name.
std::string key(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (std::isalnum(static_cast<unsigned char>(c)) != 0) {
      out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    }
  }
  return out;
}

std::optional<std::pair<double, double>> parseLatLon(std::string_view text) {
  std::string s(text);
  std::replace(s.begin(), s.end(), ',', ' ');
  std::vector<std::string> fields;
  for (size_t at = 0; at < s.size();) {
    while (at < s.size() && s[at] == ' ') ++at;
    size_t end = at;
    while (end < s.size() && s[end] != ' ') ++end;
    if (end > at) fields.push_back(s.substr(at, end - at));
    at = end;
  }
  if (fields.size() != 2) return std::nullopt;
  const auto lat = camera::parseDecimal(fields[0]), lon = camera::parseDecimal(fields[1]);
  if (!lat || !lon) return std::nullopt;
  return std::pair{*lat, *lon};
}

std::string someNames() { return "e.g. Mount Fuji, Angels Landing, Lincoln, or \"35.36, 138.73\""; }

}  // namespace

std::span<const Place> gazetteer() { return kPlaces; }

Result<GoToTarget> parseGoTo(std::string_view text) {
  if (key(text).empty())
    return makeError("go to: type a place or \"lat, lon\" (" + someNames() + ")");
  if (const auto latLon = parseLatLon(text)) {
    const auto [lat, lon] = *latLon;
    if (!std::isfinite(lat) || !std::isfinite(lon) || lat < -90 || lat > 90 || lon < -180 ||
        lon > 180) {
      return makeError("go to: \"" + std::string(text) +
                       "\": latitude must be in -90..90 and longitude in -180..180");
    }
    char name[64];
    std::snprintf(name, sizeof name, "%.5f, %.5f", lat, lon);
    return GoToTarget{name, lat, lon};
  }
  const std::string wanted = key(text);
  const Place* found = nullptr;
  size_t prefixMatches = 0;
  for (const Place& place : kPlaces) {
    const std::string name = key(place.name);
    if (name == wanted)
      return GoToTarget{place.name, place.latitudeDegrees, place.longitudeDegrees};
    if (name.rfind(wanted, 0) == 0) {
      found = &place;
      ++prefixMatches;
    }
  }
  if (prefixMatches == 1) {
    return GoToTarget{found->name, found->latitudeDegrees, found->longitudeDegrees};
  }
  if (prefixMatches > 1) {
    return makeError("go to: \"" + std::string(text) + "\" names more than one place; type more");
  }
  return makeError("go to: no place named \"" + std::string(text) + "\" (" + someNames() + ")");
}

}  // namespace globe::app
