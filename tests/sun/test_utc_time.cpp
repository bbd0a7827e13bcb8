// ISO-8601 instants with their zone: the forms people type, impossible dates and missing zones
// refused naming the text, and the calendar both ways across the eras.
#include <gtest/gtest.h>

#include "sun/delta_t.hpp"
#include "sun/utc_time.hpp"

namespace globe::sun {
namespace {

TEST(UtcTime, TheFormsOfOneInstant) {
  const double expected = 1718951400;  // 2024-06-21T06:30:00Z
  for (const std::string text :
       {"2024-06-21T06:30:00Z", "2024-06-21T06:30Z", "2024-06-21 06:30:00z", "2024-06-21t06:30:00Z",
        "2024-06-21T08:30:00+02:00", "2024-06-21T08:30+0200", "2024-06-21T08:30+02",
        "2024-06-20T23:00:00-07:30", "2024-06-21T06:30:00.000Z"}) {
    auto t = parseUtcTime(text);
    ASSERT_TRUE(t) << text << ": " << t.error();
    EXPECT_EQ(*t, expected) << text;
  }
  EXPECT_DOUBLE_EQ(*parseUtcTime("2024-06-21T06:30:00.25Z"), expected + 0.25);
  EXPECT_EQ(*parseUtcTime("2016-12-31T23:59:60Z"), *parseUtcTime("2017-01-01T00:00:00Z"))
      << "a leap second reads as the next second";
  EXPECT_EQ(*parseUtcTime("1970-01-01T00:00Z"), 0.0);
  EXPECT_EQ(*parseUtcTime("1900-01-01T00:00Z"), -2208988800.0);
  EXPECT_EQ(*parseUtcTime("2000-02-29T12:00Z"), 951825600.0) << "2000 is a leap year";
}

TEST(UtcTime, MistakesAreRefusedNamingTheText) {
  for (const std::string text :
       {"2024-06-21T06:30:00", "2024-06-21", "2023-02-29T00:00Z", "1900-02-29T00:00Z",
        "2024-13-01T00:00Z", "2024-06-31T00:00Z", "2024-06-21T24:00Z", "2024-06-21T06:60Z",
        "2024-06-21T06:30+19:00", "2024-06-21T06:30:00.Z", "21/06/2024 06:30", "now", "",
        "2024-06-21T06:30Zulu", "2024-06-21X06:30Z", "2024-6-21T06:30Z"}) {
    auto t = parseUtcTime(text);
    ASSERT_FALSE(t) << text << " read as " << *t;
    EXPECT_NE(t.error().find("'" + text + "'"), std::string::npos) << t.error();
    EXPECT_NE(t.error().find("ISO-8601"), std::string::npos) << t.error();
  }
  EXPECT_NE(parseUtcTime("2024-06-21T06:30").error().find("add Z for UTC"), std::string::npos);
}

TEST(UtcTime, CalendarBothWaysAndFormatting) {
  for (int64_t days = -1'000'000; days <= 1'000'000; days += 997) {
    const CivilDate date = civilFromDays(days);
    ASSERT_EQ(daysFromCivil(date.year, date.month, date.day), days);
  }
  EXPECT_EQ(formatUtcTime(1718951400.4), "2024-06-21T06:30:00Z");
  EXPECT_EQ(formatUtcTime(-2208988800.0), "1900-01-01T00:00:00Z");
  EXPECT_EQ(formatUtcTime(-1.0), "1969-12-31T23:59:59Z");
  EXPECT_NEAR(decimalYear(*parseUtcTime("2024-07-02T00:00Z")), 2024.5, 0.002);
  EXPECT_DOUBLE_EQ(decimalYear(*parseUtcTime("2023-01-01T00:00Z")), 2023.0);
}

// Espenak and Meeus's values at the ends of their spans, and no jump where spans meet (the
// polynomials were fitted to agree there within a second or so).
TEST(DeltaT, PublishedValuesAndContinuity) {
  EXPECT_NEAR(deltaTSeconds(1900.0), -2.79, 1e-9);
  EXPECT_NEAR(deltaTSeconds(1950.0), 29.07, 1e-9);
  EXPECT_NEAR(deltaTSeconds(1975.0), 45.45, 1e-9);
  EXPECT_NEAR(deltaTSeconds(2000.0), 63.86, 1e-9);
  EXPECT_NEAR(deltaTSeconds(2100.0), -20 + 32 * 2.8 * 2.8 - 0.5628 * 50, 1e-9);
  for (const double year : {1860.0, 1900.0, 1920.0, 1941.0, 1961.0, 1986.0, 2005.0, 2050.0,
                            2150.0}) {
    EXPECT_NEAR(deltaTSeconds(year - 1e-9), deltaTSeconds(year), 1.5) << year;
  }
  EXPECT_TRUE(std::isfinite(deltaTSeconds(-2000.0)));
  EXPECT_TRUE(std::isfinite(deltaTSeconds(6000.0)));
}

}  // namespace
}  // namespace globe::sun
