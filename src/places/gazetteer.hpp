// The bundled gazetteer (data/places/places.tsv.gz, built by tools/places/build_places.py from
// GeoNames and Natural Earth) searched by name: every place whose name or alternate name matches
// the query, folded (name_fold.hpp), best first: an exact name before one the query begins, a
// word of it begins, or it contains; then by importance (population; a peak's elevation). A
// query "NAME, WHERE" keeps the places of that country (ISO code or name: "Paris, US", "Paris,
// France") or first-level division (its code, "Paris, TX", or its name, "Paris, Texas", from the
// file's division lines).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.hpp"

namespace globe::places {

struct Place {
  std::string name;
  double latitudeDegrees = 0;
  double longitudeDegrees = 0;
  // city, country, peak, park, lake, bay, depression, pass; division (names one, never found)
  std::string kind;
  std::string countryCode;  // ISO 3166-1 alpha-2, or empty
  std::string divisionCode;
  uint64_t population = 0;
  uint64_t importance = 0;
};

class Gazetteer {
 public:
  // Reads a places file (gzip or plain TSV); errors name the file and the line.
  static Result<Gazetteer> load(const std::filesystem::path& path);

  // At most `limit` places, best first; empty when none matches.
  std::vector<const Place*> search(std::string_view query, size_t limit) const;
  size_t size() const { return places_.size(); }

 private:
  std::vector<Place> places_;                   // by importance, highest first
  std::vector<std::vector<std::string>> keys_;  // each place's folded names
};

}  // namespace globe::places
