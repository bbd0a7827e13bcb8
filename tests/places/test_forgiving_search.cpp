// Search as people type: slips of the keyboard, abbreviations and umlauts written out still find
// the place they mean, ahead of the places whose names merely begin or contain the same letters.
#include <gtest/gtest.h>

#include <filesystem>

#include "places/edit_distance.hpp"
#include "places/gazetteer.hpp"
#include "places/query_forms.hpp"
#include "tests/support/build_paths.hpp"

namespace globe::places {
namespace {

const Gazetteer& bundledPlaces() {
  static const Gazetteer gazetteer = [] {
    auto loaded =
        Gazetteer::load(std::filesystem::path(GLOBE_SOURCE_DIR) / "data/places/places.tsv.gz");
    EXPECT_TRUE(loaded) << loaded.error();
    return loaded ? std::move(*loaded) : Gazetteer{};
  }();
  return gazetteer;
}

TEST(EditDistance, CountsEachSlipOnce) {
  EXPECT_EQ(editDistanceWithin("zion", "zion", 2), 0u);
  EXPECT_EQ(editDistanceWithin("zoin", "zion", 2), 1u);               // swapped neighbours
  EXPECT_EQ(editDistanceWithin("kilimanjro", "kilimanjaro", 2), 1u);  // one left out
  EXPECT_EQ(editDistanceWithin("pariss", "paris", 2), 1u);            // one too many
  EXPECT_EQ(editDistanceWithin("londen", "london", 2), 1u);           // one wrong
  EXPECT_EQ(editDistanceWithin("istanbool", "istanbul", 2), 2u);
  EXPECT_EQ(editDistanceWithin("", "abc", 5), 3u);
  EXPECT_EQ(editDistanceWithin("abc", "", 5), 3u);
  EXPECT_EQ(editDistanceWithin("", "", 0), 0u);
}

TEST(EditDistance, StopsPastTheLimit) {
  EXPECT_EQ(editDistanceWithin("paris", "tokyo", 1), 2u);  // limit + 1, not the distance
  EXPECT_EQ(editDistanceWithin("a", "abcdefgh", 2), 3u);   // lengths alone
  EXPECT_EQ(editDistanceWithin("abcdefgh", "hgfedcba", 0), 1u);
}

TEST(EditDistance, LongerQueriesMaySlipMore) {
  EXPECT_EQ(typosAllowed(3), 0u);  // "Rio", "Uri": too short to guess at
  EXPECT_EQ(typosAllowed(4), 1u);
  EXPECT_EQ(typosAllowed(7), 1u);
  EXPECT_EQ(typosAllowed(8), 2u);
}

TEST(QueryForms, AbbreviationsBothWaysAndUmlautsWrittenOut) {
  const auto has = [](const std::vector<std::string>& forms, const char* form) {
    return std::find(forms.begin(), forms.end(), form) != forms.end();
  };
  const auto mount = queryForms("mt fuji");
  EXPECT_EQ(mount.front(), "mt fuji");  // as typed first
  EXPECT_TRUE(has(mount, "mount fuji"));
  EXPECT_TRUE(has(queryForms("saint louis"), "st louis"));
  EXPECT_TRUE(has(queryForms("n vancouver"), "north vancouver"));
  EXPECT_TRUE(has(queryForms("zuerich"), "zurich"));
  EXPECT_TRUE(has(queryForms("goettingen"), "gottingen"));
  EXPECT_EQ(queryForms("paris").size(), 1u);
  // Many abbreviations: the forms stay few.
  EXPECT_LE(queryForms("n s e w st mt ft n s e w").size(), kMaxQueryForms);
  EXPECT_TRUE(queryForms("").size() <= 1u);
}

struct Meant {
  const char* query;
  const char* name;
  const char* country;
};

// Misspelt, abbreviated or transliterated: the first place found is the one meant.
TEST(ForgivingSearch, FortyQueriesFindThePlaceMeant) {
  const Meant meant[] = {
      {"Mt Fuji", "Mount Fuji", "JP"},
      {"Mount Everst", "Mount Everest", "NP"},
      {"Everset", "Mount Everest", "NP"},
      {"Kilimanjro", "Kilimanjaro", "TZ"},
      {"Mt Kilimanjaro", "Kilimanjaro", "TZ"},
      {"Rio de Janiero", "Rio de Janeiro", "BR"},
      {"Zoin", "Zion National Park", "US"},
      {"Zuerich", "Zürich", "CH"},
      {"Muenchen", "Munich", "DE"},
      {"Koeln", "Köln", "DE"},
      {"Goettingen", "Göttingen", "DE"},
      {"Duesseldorf", "Düsseldorf", "DE"},
      {"Londn", "London", "GB"},
      {"Pariss", "Paris", "FR"},
      {"Sydeny", "Sydney", "AU"},
      {"Aukland", "Auckland", "NZ"},
      {"Bueons Aires", "Buenos Aires", "AR"},
      {"Mumbia", "Mumbai", "IN"},
      {"Ft Worth", "Fort Worth", "US"},
      {"Ft Lauderdale", "Fort Lauderdale", "US"},
      {"Saint Louis", "St. Louis", "US"},
      {"St Petersburg", "Saint Petersburg", "RU"},
      {"St Etienne", "Saint-Étienne", "FR"},
      {"St Gallen", "Sankt Gallen", "CH"},
      {"N Vancouver", "North Vancouver", "CA"},
      {"W Palm Beach", "West Palm Beach", "US"},
      {"E London", "East London", "ZA"},
      {"S Lake Tahoe", "South Lake Tahoe", "US"},
      {"Mt Blanc", "Mont Blanc", "FR"},
      {"Materhorn", "Matterhorn", "CH"},
      {"Reykjavk", "Reykjavík", "IS"},
      {"Amsterdm", "Amsterdam", "NL"},
      {"Barcelonna", "Barcelona", "ES"},
      {"Johanesburg", "Johannesburg", "ZA"},
      {"Philadelpia", "Philadelphia", "US"},
      {"Los Angelos", "Los Angeles", "US"},
      {"San Fransisco", "San Francisco", "US"},
      {"Istanbool", "Istanbul", "TR"},
      {"Moskow", "Moscow", "RU"},
      {"Beijng", "Beijing", "CN"},
      {"Vancover", "Vancouver", "CA"},
      {"Grand Canyn", "Grand Canyon", "US"},
  };
  size_t wrong = 0;
  for (const Meant& m : meant) {
    const auto found = bundledPlaces().search(m.query, 3);
    ASSERT_FALSE(found.empty()) << m.query;
    EXPECT_EQ(found[0]->name, m.name) << m.query;
    EXPECT_EQ(found[0]->countryCode, m.country) << m.query;
    if (found[0]->name != m.name) ++wrong;
  }
  EXPECT_GE(std::size(meant), 40u);
  EXPECT_EQ(wrong, 0u);
}

// Forgiving does not mean guessing: a prefix of a name people type still finds that name first,
// very short queries are not "corrected", and nonsense finds nothing.
TEST(ForgivingSearch, ExactNamesAndPrefixesStillComeFirst) {
  const Meant meant[] = {
      {"Lond", "London", "GB"},  // a prefix, not Lund one slip away
      {"Zion", "Zion National Park", "US"},
      {"Fujinom", "Fujinomiya", "JP"},
      {"Paris", "Paris", "FR"},
      {"Bern", "Bern", "CH"},  // not Berne, IN, nor Bergen
  };
  for (const Meant& m : meant) {
    const auto found = bundledPlaces().search(m.query, 3);
    ASSERT_FALSE(found.empty()) << m.query;
    EXPECT_EQ(found[0]->name, m.name) << m.query;
    EXPECT_EQ(found[0]->countryCode, m.country) << m.query;
  }
  EXPECT_TRUE(bundledPlaces().search("Xqzzyx", 3).empty());
  EXPECT_TRUE(bundledPlaces().search("Qqq", 3).empty());  // three letters: no slips allowed
}

}  // namespace
}  // namespace globe::places
