// Positions typed every common way, and text that is a name, not a position.
#include <gtest/gtest.h>

#include <string>

#include "places/coordinates.hpp"
#include "places/name_fold.hpp"

namespace globe::places {
namespace {

void expectPosition(const std::string& text, double lat, double lon) {
  SCOPED_TRACE(text);
  const auto parsed = parseCoordinates(text);
  ASSERT_TRUE(parsed.has_value()) << "not read as a position";
  ASSERT_TRUE(*parsed) << parsed->error();
  EXPECT_NEAR((*parsed)->latitudeDegrees, lat, 1e-4);
  EXPECT_NEAR((*parsed)->longitudeDegrees, lon, 1e-4);
}

TEST(Coordinates, DecimalInEitherOrder) {
  expectPosition("35.36, 138.73", 35.36, 138.73);  // latitude first, as map sites take it
  expectPosition("35.36 138.73", 35.36, 138.73);
  expectPosition("  -33.9   18.4 ", -33.9, 18.4);
  expectPosition("138.73, 35.36", 35.36, 138.73);    // the first cannot be a latitude
  expectPosition("-112.95, 37.27", 37.27, -112.95);  // lon, lat as GeoJSON writes it
  expectPosition("+48.8566;+2.3522", 48.8566, 2.3522);
  expectPosition("0 0", 0, 0);
  expectPosition("-90, 180", -90, 180);
}

TEST(Coordinates, HemisphereLetters) {
  expectPosition("35.36N 138.73E", 35.36, 138.73);
  expectPosition("35.36 N, 138.73 E", 35.36, 138.73);
  expectPosition("N35.36 E138.73", 35.36, 138.73);
  expectPosition("138.73E 35.36N", 35.36, 138.73);  // the letters say which is which
  expectPosition("33.92S 18.42E", -33.92, 18.42);
  expectPosition("40.7128 n, 74.0060 w", 40.7128, -74.006);
  expectPosition("S 22.9 W 43.2", -22.9, -43.2);
}

TEST(Coordinates, DegreesMinutesSeconds) {
  expectPosition("35°21'38\"N 138°43'39\"E", 35 + 21 / 60.0 + 38 / 3600.0,
                 138 + 43 / 60.0 + 39 / 3600.0);
  expectPosition("35° 21′ 38″ N, 138° 43′ 39″ E", 35 + 21 / 60.0 + 38 / 3600.0,
                 138 + 43 / 60.0 + 39 / 3600.0);
  expectPosition("35 21 38 N 138 43 39 E", 35 + 21 / 60.0 + 38 / 3600.0,
                 138 + 43 / 60.0 + 39 / 3600.0);
  expectPosition("35d21m38s N 138d43m39s E", 35 + 21 / 60.0 + 38 / 3600.0,
                 138 + 43 / 60.0 + 39 / 3600.0);
  expectPosition("33°55.2'S 18°25.2'E", -(33 + 55.2 / 60), 18 + 25.2 / 60);  // degrees, minutes
  expectPosition("-33 55 12, 18 25 12", -(33 + 55 / 60.0 + 12 / 3600.0),
                 18 + 25 / 60.0 + 12 / 3600.0);
}

TEST(Coordinates, OutOfRangeOrContradictoryIsAnErrorSayingWhy) {
  for (const char* text : {"95, 200", "35 61 00 N 138 43 39 E", "35N 36S", "200, 200"}) {
    SCOPED_TRACE(text);
    const auto parsed = parseCoordinates(text);
    ASSERT_TRUE(parsed.has_value());
    ASSERT_FALSE(*parsed);
    EXPECT_NE(parsed->error().find(text), std::string::npos) << parsed->error();
  }
}

TEST(Coordinates, NamesAreNotPositions) {
  for (const char* text :
       {"Paris", "K2", "Mount Fuji", "Paris, US", "", "  ", "35.36", "New York 10", "1 2 3", "E"}) {
    EXPECT_FALSE(parseCoordinates(text).has_value()) << text;
  }
}

TEST(NameFold, AccentsCaseAndPunctuation) {
  EXPECT_EQ(foldName("Zürich"), "zurich");
  EXPECT_EQ(foldName("São Paulo"), "sao paulo");
  EXPECT_EQ(foldName("ŁÓDŹ"), "lodz");
  EXPECT_EQ(foldName("Straße"), "strasse");
  EXPECT_EQ(foldName("  Mt.  Everest "), "mt everest");
  EXPECT_EQ(foldName("Côte d'Ivoire"), "cote d ivoire");
  EXPECT_EQ(foldName("Zu\xCC\x88rich"), "zurich");  // a combining diaeresis
  EXPECT_EQ(foldName("東京 Tokyo"), "tokyo");
  EXPECT_EQ(foldName("bad \xFF\xFE bytes"), "bad bytes");
}

TEST(NameFold, AsciiForADisplayThatDrawsNothingElse) {
  EXPECT_EQ(asciiForDisplay("Zürich, CH"), "Zurich, CH");
  EXPECT_EQ(asciiForDisplay("Ålesund"), "Alesund");
  EXPECT_EQ(asciiForDisplay("São Paulo"), "Sao Paulo");
  EXPECT_EQ(asciiForDisplay("Łódź"), "Lodz");
  EXPECT_EQ(asciiForDisplay("東京"), "??");
  EXPECT_EQ(asciiForDisplay("a\tb\xFF"), "a?b?");
}

}  // namespace
}  // namespace globe::places
