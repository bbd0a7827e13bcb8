#include "places/gazetteer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "formats/gzip_bytes.hpp"
#include "places/name_fold.hpp"
#include "transport/atomic_file.hpp"

namespace globe::places {
namespace {

constexpr uint64_t kMaxPlacesFileBytes = uint64_t{1} << 30;
constexpr std::string_view kCountry = "country";
// A division line only names a region for "NAME, DIVISION": its position is no place to go.
constexpr std::string_view kDivision = "division";

std::vector<std::string_view> split(std::string_view line, char separator) {
  std::vector<std::string_view> fields;
  size_t start = 0;
  for (size_t i = 0; i <= line.size(); ++i) {
    if (i == line.size() || line[i] == separator) {
      fields.push_back(line.substr(start, i - start));
      start = i + 1;
    }
  }
  return fields;
}

template <class T>
bool parseNumber(std::string_view text, T& value) {
  if (text.empty()) {
    value = 0;
    return true;
  }
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

bool parseDouble(std::string_view text, double& value) {
  // from_chars for double is in GCC 12's libstdc++.
  return parseNumber(text, value);
}

std::string withoutSpaces(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c != ' ') out.push_back(c);
  }
  return out;
}

// How well a folded name matches the folded query: 0 the same, 1 it begins so, 2 a word of it
// begins so, 3 it holds it; 4 none.
int matchTier(const std::string& key, const std::string& query) {
  if (key == query) return 0;
  if (key.size() > query.size() && key.compare(0, query.size(), query) == 0) return 1;
  for (size_t at = key.find(' '); at != std::string::npos; at = key.find(' ', at + 1)) {
    if (key.compare(at + 1, query.size(), query) == 0) return 2;
  }
  if (query.size() >= 3 && key.find(query) != std::string::npos) return 3;
  if (withoutSpaces(key) == withoutSpaces(query)) return 0;  // "usa" for "u s a"
  return 4;
}

}  // namespace

Result<Gazetteer> Gazetteer::load(const std::filesystem::path& path) {
  auto bytes = transport::readWholeFile(path, kMaxPlacesFileBytes);
  if (!bytes) return Error{bytes.error()};
  auto text = formats::gunzipIfNeeded(*bytes, path.string(), kMaxPlacesFileBytes);
  if (!text) return Error{text.error()};
  const std::string_view all(reinterpret_cast<const char*>(text->data()), text->size());
  Gazetteer g;
  size_t lineNumber = 0;
  for (std::string_view line : split(all, '\n')) {
    ++lineNumber;
    if (line.empty()) continue;
    const auto f = split(line, '\t');
    Place place;
    if (f.size() != 10 || f[0].empty() || f[1].empty() ||
        !parseDouble(f[2], place.latitudeDegrees) || !parseDouble(f[3], place.longitudeDegrees) ||
        !parseNumber(f[7], place.population) || !parseNumber(f[9], place.importance) ||
        std::fabs(place.latitudeDegrees) > 90 || std::fabs(place.longitudeDegrees) > 180) {
      return makeError(path.string() + ":" + std::to_string(lineNumber) +
                       ": not a place line (name, keys, lat, lon, kind, country, division, "
                       "population, elevation, importance)");
    }
    place.name = std::string(f[0]);
    place.kind = std::string(f[4]);
    place.countryCode = std::string(f[5]);
    place.divisionCode = std::string(f[6]);
    std::vector<std::string> keys;
    for (std::string_view key : split(f[1], '|')) {
      if (!key.empty()) keys.emplace_back(key);
    }
    g.places_.push_back(std::move(place));
    g.keys_.push_back(std::move(keys));
  }
  if (g.places_.empty()) return makeError(path.string() + ": no places");
  // Kept by importance, as the builder writes them; sorted again for files made otherwise.
  std::vector<size_t> order(g.places_.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return g.places_[a].importance > g.places_[b].importance;
  });
  Gazetteer sorted;
  for (size_t i : order) {
    sorted.places_.push_back(std::move(g.places_[i]));
    sorted.keys_.push_back(std::move(g.keys_[i]));
  }
  return sorted;
}

std::vector<const Place*> Gazetteer::search(std::string_view query, size_t limit) const {
  // "NAME, WHERE": WHERE a country (code or name) or a division code.
  std::string name(query);
  std::string where;
  if (const size_t comma = name.rfind(','); comma != std::string::npos) {
    where = foldName(name.substr(comma + 1));
    name = name.substr(0, comma);
  }
  const std::string wanted = foldName(name);
  if (wanted.empty()) return {};
  // WHERE as a country (its code or a name) or a first-level division (its code, or a name
  // from the builder's division lines: "Texas", "Western Australia").
  std::vector<std::string> countries;
  std::vector<std::pair<std::string, std::string>> divisions;  // country, division code
  if (!where.empty()) {
    const auto names = [&](const std::vector<std::string>& keys) {
      return std::any_of(keys.begin(), keys.end(), [&](const std::string& k) {
        return k == where || withoutSpaces(k) == withoutSpaces(where);
      });
    };
    for (size_t i = 0; i < places_.size(); ++i) {
      const Place& p = places_[i];
      if (p.kind == kCountry && (names(keys_[i]) || foldName(p.countryCode) == where)) {
        countries.push_back(p.countryCode);
      } else if (p.kind == kDivision && names(keys_[i])) {
        divisions.emplace_back(p.countryCode, p.divisionCode);
      }
    }
  }
  const auto inWhere = [&](const Place& p) {
    if (where.empty()) return true;
    if (std::find(countries.begin(), countries.end(), p.countryCode) != countries.end())
      return true;
    if (std::find(divisions.begin(), divisions.end(), std::pair(p.countryCode, p.divisionCode)) !=
        divisions.end()) {
      return true;
    }
    return foldName(p.countryCode) == where || foldName(p.divisionCode) == where;
  };
  // Places are by importance already: the first `limit` of each tier, tiers in order.
  std::vector<std::vector<const Place*>> tiers(4);
  for (size_t i = 0; i < places_.size(); ++i) {
    int best = 4;
    for (const std::string& key : keys_[i]) best = std::min(best, matchTier(key, wanted));
    if (best >= 4 || tiers[static_cast<size_t>(best)].size() >= limit) continue;
    if (places_[i].kind == kDivision || !inWhere(places_[i])) continue;
    tiers[static_cast<size_t>(best)].push_back(&places_[i]);
  }
  std::vector<const Place*> found;
  for (const auto& tier : tiers) {
    for (const Place* p : tier) {
      if (found.size() < limit) found.push_back(p);
    }
  }
  return found;
}

}  // namespace globe::places
