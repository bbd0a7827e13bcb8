#include "places/gazetteer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "compression/gzip_bytes.hpp"
#include "places/edit_distance.hpp"
#include "places/name_fold.hpp"
#include "places/query_forms.hpp"
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

// The same letters, spaces aside ("usa" and "u s a"), without copying: it runs for every key.
bool sameWithoutSpaces(std::string_view a, std::string_view b) {
  size_t i = 0, j = 0;
  while (true) {
    while (i < a.size() && a[i] == ' ') ++i;
    while (j < b.size() && b[j] == ' ') ++j;
    if (i == a.size() || j == b.size()) return i == a.size() && j == b.size();
    if (a[i++] != b[j++]) return false;
  }
}

// How well a place's folded names match the query's forms, best first: the same name, its own
// name beginning so, one typing slip from a name, two slips, another of its names beginning so,
// a word of a name beginning so, a name holding it; kNoMatch none. Slips rank above an alternate
// name's beginning: "Zoin" means Zion rather than Joinville, whose Lithuanian name is
// "Zoinvilis".
enum Tier : size_t {
  kSame,
  kOwnPrefix,
  kOneSlip,
  kTwoSlips,
  kOtherPrefix,
  kWord,
  kHolds,
  kNoMatch
};

struct Match {
  Tier tier = kNoMatch;
  bool ownName = false;  // the name the place goes by, not a translation or former name
};

// Among places one or two slips away, one whose own name was mistyped counts as this many times
// as important: "Aukland" is Auckland (417,910 people), not Oakland (419,267, whose Lithuanian
// name is "Oukland"), while "Zoin" is still Zion National Park, not Zlín.
constexpr uint64_t kOwnNameSlipWeight = 4;

bool beginsWith(const std::string& key, const std::string& form) {
  return key.size() > form.size() && key.compare(0, form.size(), form) == 0;
}

Tier textTier(const std::string& key, const std::string& form, bool ownName) {
  if (key == form) return kSame;
  if (beginsWith(key, form)) return ownName ? kOwnPrefix : kOtherPrefix;
  for (size_t at = key.find(' '); at != std::string::npos; at = key.find(' ', at + 1)) {
    if (key.compare(at + 1, form.size(), form) == 0) return kWord;
  }
  if (form.size() >= 3 && key.find(form) != std::string::npos) return kHolds;
  if (sameWithoutSpaces(key, form)) return kSame;  // "usa" for "u s a"
  return kNoMatch;
}

Tier slipTier(const std::string& key, const std::string& form) {
  const size_t allowed = typosAllowed(form.size());
  if (allowed == 0) return kNoMatch;
  const size_t slips = editDistanceWithin(key, form, allowed);
  if (slips > allowed) return kNoMatch;
  return slips == 0 ? kSame : slips == 1 ? kOneSlip : kTwoSlips;
}

void keepBetter(Match& best, Tier tier, bool ownName) {
  if (tier < best.tier || (tier == best.tier && ownName && !best.ownName)) best = {tier, ownName};
}

Match placeMatch(const std::vector<std::string>& keys, const std::vector<std::string>& forms) {
  Match best;
  for (const std::string& form : forms) {
    for (size_t k = 0; k < keys.size() && best.tier != kSame; ++k)
      keepBetter(best, textTier(keys[k], form, k == 0), k == 0);
  }
  if (best.tier < kOneSlip) return best;
  for (const std::string& form : forms) {
    for (size_t k = 0; k < keys.size(); ++k) keepBetter(best, slipTier(keys[k], form), k == 0);
  }
  return best;
}

uint64_t rankWeight(const Place& place, const Match& match) {
  const bool slip = match.tier == kOneSlip || match.tier == kTwoSlips;
  return slip && match.ownName ? place.importance * kOwnNameSlipWeight : place.importance;
}

}  // namespace

Result<Gazetteer> Gazetteer::load(const std::filesystem::path& path) {
  auto bytes = transport::readWholeFile(path, kMaxPlacesFileBytes);
  if (!bytes) return Error{bytes.error()};
  auto text = compression::gunzipIfNeeded(*bytes, path.string(), kMaxPlacesFileBytes);
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
  const std::vector<std::string> forms = queryForms(wanted);
  // WHERE as a country (its code or a name) or a first-level division (its code, or a name
  // from the builder's division lines: "Texas", "Western Australia").
  std::vector<std::string> countries;
  std::vector<std::pair<std::string, std::string>> divisions;  // country, division code
  if (!where.empty()) {
    const auto names = [&](const std::vector<std::string>& keys) {
      return std::any_of(keys.begin(), keys.end(), [&](const std::string& k) {
        return k == where || sameWithoutSpaces(k, where);
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
  // Each tier's places by their weight (importance: the order they are kept in), tiers in order.
  std::vector<std::vector<std::pair<uint64_t, const Place*>>> tiers(kNoMatch);
  for (size_t i = 0; i < places_.size(); ++i) {
    if (places_[i].kind == kDivision) continue;
    const Match match = placeMatch(keys_[i], forms);
    if (match.tier == kNoMatch || !inWhere(places_[i])) continue;
    tiers[match.tier].emplace_back(rankWeight(places_[i], match), &places_[i]);
  }
  std::vector<const Place*> found;
  for (auto& tier : tiers) {
    std::stable_sort(tier.begin(), tier.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    for (const auto& [weight, p] : tier) {
      if (found.size() < limit) found.push_back(p);
    }
  }
  return found;
}

}  // namespace globe::places
