// Instants as the command line and camera paths give them: ISO-8601 date and time with its zone
// ("2024-06-21T06:30:00+02:00", "2024-06-21T04:30Z"), held as seconds since 1970-01-01T00:00Z
// (UTC, leap seconds not counted, as POSIX time).
#pragma once

#include <cstdint>
#include <string>

#include "core/result.hpp"

namespace globe::sun {

// "YYYY-MM-DDTHH:MM[:SS[.fff]]" then "Z" or an offset "±HH:MM", "±HHMM" or "±HH" ('T' may be a
// space, letters in either case). A time without a zone is refused (it would be a guess), as
// are impossible dates (2023-02-29), hours past 23 and offsets past ±18:00; a leap second (:60)
// is read as the next second. Errors quote the text and show the form.
Result<double> parseUtcTime(const std::string& text);

// "YYYY-MM-DDTHH:MM:SSZ", to the nearest second.
std::string formatUtcTime(double unixSeconds);

// The year with its fraction (2024.5: the middle of 2024), for ΔT.
double decimalYear(double unixSeconds);

// Days since 1970-01-01 of a proleptic Gregorian date, and back.
int64_t daysFromCivil(int64_t year, unsigned month, unsigned day);
struct CivilDate {
  int64_t year;
  unsigned month, day;
};
CivilDate civilFromDays(int64_t days);

}  // namespace globe::sun
