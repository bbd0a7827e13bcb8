// `globe search QUERY [--limit N] [--places FILE]`: places by name from the bundled gazetteer,
// or a typed position, as CSV lines `name,lon,lat,kind,population`, best first.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/globe/places_file.hpp"
#include "apps/globe/subcommands.hpp"
#include "places/coordinates.hpp"

namespace globe::app {
namespace {

struct SearchArguments {
  std::string query;
  size_t limit = 10;
  std::string placesFile;
};

// A CSV field: quoted when it holds a comma or a quote.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

int runSearchCommand(const SearchArguments& arguments) {
  if (auto position = places::parseCoordinates(arguments.query)) {
    if (!*position) {
      std::fprintf(stderr, "globe search: %s\n", position->error().c_str());
      return 1;
    }
    char name[64];
    std::snprintf(name, sizeof name, "%.6f, %.6f", (*position)->latitudeDegrees,
                  (*position)->longitudeDegrees);
    std::printf("name,lon,lat,kind,population\n%s,%.6f,%.6f,position,0\n", csvField(name).c_str(),
                (*position)->longitudeDegrees, (*position)->latitudeDegrees);
    return 0;
  }
  auto gazetteer = loadPlaces(arguments.placesFile);
  if (!gazetteer) {
    std::fprintf(stderr, "globe search: %s\n", gazetteer.error().c_str());
    return 1;
  }
  const auto found = (*gazetteer)->search(arguments.query, arguments.limit);
  if (found.empty()) {
    std::fprintf(stderr, "globe search: no place named \"%s\"\n", arguments.query.c_str());
    return 1;
  }
  std::printf("name,lon,lat,kind,population\n");
  for (const places::Place* p : found) {
    const std::string where =
        p->countryCode.empty() || p->kind == "country" ? p->name : p->name + ", " + p->countryCode;
    std::printf("%s,%.5f,%.5f,%s,%llu\n", csvField(where).c_str(), p->longitudeDegrees,
                p->latitudeDegrees, p->kind.c_str(),
                static_cast<unsigned long long>(p->population));
  }
  return 0;
}

}  // namespace

Subcommand addSearchCommand(CLI::App& app, CommonArguments&) {
  auto arguments = std::make_shared<SearchArguments>();
  CLI::App* search = app.add_subcommand(
      "search",
      "find places by name (accents and case ignored; \"NAME, COUNTRY\" picks among namesakes) or "
      "read a position (\"35.36, 138.73\", \"35°21'38\\\"N 138°43'39\\\"E\"): prints "
      "name,lon,lat,kind,population, best first. Places: GeoNames (CC BY 4.0) and Natural Earth");
  search->add_option("QUERY", arguments->query, "a place's name, or a position")->required();
  search->add_option("--limit", arguments->limit, "at most this many places (default 10)")
      ->check(CLI::Range(1, 1000));
  search->add_option("--places", arguments->placesFile,
                     "the gazetteer (default: $GLOBE_PLACES, else the bundled places.tsv.gz)");
  return {search, [arguments](const CommandContext&) { return runSearchCommand(*arguments); }};
}

}  // namespace globe::app
