// The bundled gazetteer (data/places/places.tsv.gz): famous places of every continent come first
// for their names, accents and case ignored, a country after a comma, peaks by their name alone.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "places/gazetteer.hpp"
#include "tests/support/build_paths.hpp"

namespace globe::places {
namespace {

const std::filesystem::path kPlaces =
    std::filesystem::path(GLOBE_SOURCE_DIR) / "data/places/places.tsv.gz";

const Gazetteer& bundled() {
  static const Gazetteer gazetteer = [] {
    auto loaded = Gazetteer::load(kPlaces);
    EXPECT_TRUE(loaded) << loaded.error();
    return loaded ? std::move(*loaded) : Gazetteer{};
  }();
  return gazetteer;
}

struct Famous {
  const char* query;
  const char* name;
  const char* country;
  double lat, lon;  // within 0.5 degrees
};

TEST(Gazetteer, FamousPlacesOfEveryContinentComeFirst) {
  ASSERT_GT(bundled().size(), 130000u);
  const Famous famous[] = {
      {"Paris", "Paris", "FR", 48.85, 2.35},
      {"London", "London", "GB", 51.51, -0.13},
      {"Tokyo", "Tokyo", "JP", 35.69, 139.69},
      {"Zurich", "Zürich", "CH", 47.37, 8.55},
      {"Sao Paulo", "São Paulo", "BR", -23.55, -46.64},
      {"sao paulo", "São Paulo", "BR", -23.55, -46.64},
      {"Cairo", "Cairo", "EG", 30.06, 31.25},
      {"Lagos", "Lagos", "NG", 6.45, 3.39},
      {"Sydney", "Sydney", "AU", -33.87, 151.21},
      {"Auckland", "Auckland", "NZ", -36.85, 174.76},
      {"New York", "New York City", "US", 40.71, -74.01},
      {"Mexico City", "Mexico City", "MX", 19.43, -99.13},
      {"Buenos Aires", "Buenos Aires", "AR", -34.61, -58.38},
      {"Mumbai", "Mumbai", "IN", 19.07, 72.88},
      {"Fuji", "Mount Fuji", "JP", 35.36, 138.73},
      {"Everest", "Mount Everest", "NP", 27.99, 86.93},
      {"Kilimanjaro", "Kilimanjaro", "TZ", -3.07, 37.36},
      {"Japan", "Japan", "JP", 36.0, 137.0},
      {"Munchen", "Munich", "DE", 48.14, 11.58},
      {"Wien", "Vienna", "AT", 48.21, 16.37},
      {"Reykjavik", "Reykjavík", "IS", 64.14, -21.9},
      {"Zion", "Zion National Park", "US", 37.3, -113.03},
  };
  for (const Famous& f : famous) {
    SCOPED_TRACE(f.query);
    const auto found = bundled().search(f.query, 5);
    ASSERT_FALSE(found.empty());
    EXPECT_EQ(found[0]->name, f.name);
    EXPECT_EQ(found[0]->countryCode, f.country);
    EXPECT_NEAR(found[0]->latitudeDegrees, f.lat, 0.5);
    EXPECT_NEAR(found[0]->longitudeDegrees, f.lon, 0.5);
  }
}

TEST(Gazetteer, ACountryOrDivisionAfterACommaChoosesAmongNamesakes) {
  const auto texas = bundled().search("Paris, US", 3);
  ASSERT_FALSE(texas.empty());
  EXPECT_EQ(texas[0]->countryCode, "US");
  EXPECT_EQ(texas[0]->name, "Paris");
  const auto byName = bundled().search("paris, united states", 3);
  ASSERT_FALSE(byName.empty());
  EXPECT_EQ(byName[0]->countryCode, "US");
  const auto tennessee = bundled().search("Paris, TN", 3);
  ASSERT_FALSE(tennessee.empty());
  EXPECT_EQ(tennessee[0]->divisionCode, "TN");
  const auto ontario = bundled().search("Paris, Canada", 3);
  ASSERT_FALSE(ontario.empty());
  EXPECT_EQ(ontario[0]->countryCode, "CA");
  EXPECT_TRUE(bundled().search("Paris, Atlantis", 3).empty());
}

// Divisions by name (tools/places/divisions.tsv, carried into the file by the builder): the
// namesake in that state, province or nation, accents and case folded; the bare name is still
// the best known one.
TEST(Gazetteer, ADivisionByNameChoosesAmongNamesakes) {
  struct Case {
    const char* query;
    const char* name;
    const char* country;
    const char* division;
    double lat, lon;  // within 0.3 degrees
  };
  for (const Case& c :
       {Case{"Paris, Texas", "Paris", "US", "TX", 33.66, -95.56},
        Case{"Portland, Oregon", "Portland", "US", "OR", 45.52, -122.68},
        Case{"London, Ontario", "London", "CA", "08", 42.98, -81.23},
        Case{"Perth, Western Australia", "Perth", "AU", "08", -31.95, 115.86},
        Case{"Cambridge, England", "Cambridge", "GB", "ENG", 52.2, 0.12},
        Case{"  portland ,  OREGON ", "Portland", "US", "OR", 45.52, -122.68},
        Case{"Munster, Nordrhein-Westfalen", "Münster", "DE", "07", 51.96, 7.63},
        Case{"Leon, Guanajuato", "León de los Aldama", "MX", "11", 21.12, -101.68},
        Case{"Santa Maria, Rio Grande do Sul", "Santa Maria", "BR", "23", -29.68, -53.81}}) {
    SCOPED_TRACE(c.query);
    const auto found = bundled().search(c.query, 3);
    ASSERT_FALSE(found.empty());
    EXPECT_EQ(found[0]->name, c.name);
    EXPECT_EQ(found[0]->countryCode, c.country);
    EXPECT_EQ(found[0]->divisionCode, c.division);
    EXPECT_NEAR(found[0]->latitudeDegrees, c.lat, 0.3);
    EXPECT_NEAR(found[0]->longitudeDegrees, c.lon, 0.3);
    for (const Place* p : found) EXPECT_EQ(p->divisionCode, c.division) << p->name;
  }
  // The bare name and the country by name as before; a division is never a result itself.
  const auto paris = bundled().search("Paris", 3);
  ASSERT_FALSE(paris.empty());
  EXPECT_EQ(paris[0]->countryCode, "FR");
  const auto france = bundled().search("Paris, France", 3);
  ASSERT_FALSE(france.empty());
  EXPECT_EQ(france[0]->countryCode, "FR");
  for (const Place* p : bundled().search("Texas", 20)) EXPECT_NE(p->kind, "division");
  EXPECT_TRUE(bundled().search("Paris, Narnia", 3).empty());
}

TEST(Gazetteer, PrefixesAndWordsFindPlacesBestKnownFirst) {
  const auto fujino = bundled().search("Fujinom", 3);
  ASSERT_FALSE(fujino.empty());
  EXPECT_EQ(fujino[0]->name, "Fujinomiya");
  const auto angels = bundled().search("angels", 3);  // a word of "Angels Landing"? a city first
  ASSERT_FALSE(angels.empty());
  const auto none = bundled().search("Xqzzyx", 3);
  EXPECT_TRUE(none.empty());
  EXPECT_TRUE(bundled().search("", 3).empty());
  EXPECT_EQ(bundled().search("Springfield", 10).size(), 10u);  // many: as many as asked
}

TEST(Gazetteer, ABadFileIsAnErrorNamingItAndTheLine) {
  const auto dir = std::filesystem::temp_directory_path() / "globe-places-bad";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "bad.tsv")
      << "Paris\tparis\t48.85\t2.35\tcity\tFR\t11\t2138551\t42\t2138551\n"
      << "Nowhere\tnowhere\t123\t2\tcity\t\t\t0\t\t0\n";
  const auto bad = Gazetteer::load(dir / "bad.tsv");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("bad.tsv:2"), std::string::npos) << bad.error();
  const auto missing = Gazetteer::load(dir / "missing.tsv");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("missing.tsv"), std::string::npos) << missing.error();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace globe::places
