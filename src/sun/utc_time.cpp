#include "sun/utc_time.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string_view>

namespace globe::sun {
namespace {

constexpr double kSecondsPerDay = 86400;

bool isLeapYear(int64_t y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

unsigned daysInMonth(int64_t year, unsigned month) {
  constexpr unsigned kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return month == 2 && isLeapYear(year) ? 29 : kDays[month - 1];
}

// Reads exactly `digits` decimal digits at text[at], advancing at.
std::optional<int> digitsAt(std::string_view text, size_t& at, size_t digits) {
  if (at + digits > text.size()) return std::nullopt;
  int value = 0;
  for (size_t i = 0; i < digits; ++i) {
    const char c = text[at + i];
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
    value = value * 10 + (c - '0');
  }
  at += digits;
  return value;
}

bool take(std::string_view text, size_t& at, char c) {
  if (at < text.size() && std::toupper(static_cast<unsigned char>(text[at])) == c) {
    ++at;
    return true;
  }
  return false;
}

// The zone at text[at..]: "Z" or ±HH[[:]MM]; seconds east of UTC.
std::optional<int> zoneAt(std::string_view text, size_t at) {
  if (take(text, at, 'Z')) return at == text.size() ? std::optional<int>(0) : std::nullopt;
  if (at >= text.size() || (text[at] != '+' && text[at] != '-')) return std::nullopt;
  const int sign = text[at++] == '-' ? -1 : 1;
  const auto hours = digitsAt(text, at, 2);
  if (!hours) return std::nullopt;
  int minutes = 0;
  if (at < text.size()) {
    take(text, at, ':');
    const auto m = digitsAt(text, at, 2);
    if (!m || *m > 59) return std::nullopt;
    minutes = *m;
  }
  if (at != text.size() || *hours * 60 + minutes > 18 * 60) return std::nullopt;
  return sign * (*hours * 3600 + minutes * 60);
}

}  // namespace

int64_t daysFromCivil(int64_t y, unsigned m, unsigned d) {
  y -= m <= 2;
  const int64_t era = (y >= 0 ? y : y - 399) / 400;
  const auto yearOfEra = static_cast<unsigned>(y - era * 400);
  const unsigned dayOfYear = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned dayOfEra = yearOfEra * 365 + yearOfEra / 4 - yearOfEra / 100 + dayOfYear;
  return era * 146097 + static_cast<int64_t>(dayOfEra) - 719468;
}

CivilDate civilFromDays(int64_t z) {
  z += 719468;
  const int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const auto dayOfEra = static_cast<unsigned>(z - era * 146097);
  const unsigned yearOfEra =
      (dayOfEra - dayOfEra / 1460 + dayOfEra / 36524 - dayOfEra / 146096) / 365;
  const unsigned dayOfYear = dayOfEra - (365 * yearOfEra + yearOfEra / 4 - yearOfEra / 100);
  const unsigned mp = (5 * dayOfYear + 2) / 153;
  const unsigned day = dayOfYear - (153 * mp + 2) / 5 + 1;
  const unsigned month = mp < 10 ? mp + 3 : mp - 9;
  return {static_cast<int64_t>(yearOfEra) + era * 400 + (month <= 2), month, day};
}

Result<double> parseUtcTime(const std::string& text) {
  const auto refuse = [&](const std::string& why) -> Result<double> {
    return makeError("time '" + text + "': " + why +
                     " (ISO-8601 with its zone, e.g. 2024-06-21T06:30:00Z or "
                     "2024-06-21T08:30+02:00)");
  };
  size_t at = 0;
  const auto year = digitsAt(text, at, 4);
  const bool dateSeparators = take(text, at, '-');
  const auto month = digitsAt(text, at, 2);
  const bool secondSeparator = take(text, at, '-');
  const auto day = digitsAt(text, at, 2);
  if (!year || !month || !day || !dateSeparators || !secondSeparator) {
    return refuse("not a date YYYY-MM-DD");
  }
  if (*month < 1 || *month > 12 || *day < 1 ||
      static_cast<unsigned>(*day) > daysInMonth(*year, static_cast<unsigned>(*month))) {
    return refuse("no such date");
  }
  if (at == text.size()) return refuse("no time of day and zone");
  if (!take(text, at, 'T') && !take(text, at, ' ')) return refuse("no 'T' before the time");
  const auto hour = digitsAt(text, at, 2);
  const bool colon = take(text, at, ':');
  const auto minute = digitsAt(text, at, 2);
  if (!hour || !colon || !minute || *hour > 23 || *minute > 59) return refuse("not a time HH:MM");
  double second = 0;
  if (take(text, at, ':')) {
    const auto whole = digitsAt(text, at, 2);
    if (!whole || *whole > 60) return refuse("not seconds SS");
    second = *whole;
    if (take(text, at, '.') || take(text, at, ',')) {
      double scale = 0.1;
      const size_t first = at;
      for (; at < text.size() && std::isdigit(static_cast<unsigned char>(text[at])); ++at) {
        second += (text[at] - '0') * scale;
        scale /= 10;
      }
      if (at == first) return refuse("no digits after the decimal mark");
    }
  }
  if (at == text.size()) return refuse("no zone: add Z for UTC or an offset such as +02:00");
  const auto zone = zoneAt(text, at);
  if (!zone) return refuse("the zone is not Z or ±HH:MM (up to ±18:00)");
  const int64_t days =
      daysFromCivil(*year, static_cast<unsigned>(*month), static_cast<unsigned>(*day));
  return static_cast<double>(days) * kSecondsPerDay + *hour * 3600.0 + *minute * 60.0 + second -
         *zone;
}

std::string formatUtcTime(double unixSeconds) {
  const auto whole = static_cast<int64_t>(std::llround(unixSeconds));
  int64_t days = whole / 86400, seconds = whole % 86400;
  if (seconds < 0) {
    seconds += 86400;
    --days;
  }
  const CivilDate date = civilFromDays(days);
  char text[40];
  std::snprintf(text, sizeof text, "%04lld-%02u-%02uT%02lld:%02lld:%02lldZ",
                static_cast<long long>(date.year), date.month, date.day,
                static_cast<long long>(seconds / 3600), static_cast<long long>(seconds / 60 % 60),
                static_cast<long long>(seconds % 60));
  return text;
}

double decimalYear(double unixSeconds) {
  const auto days = static_cast<int64_t>(std::floor(unixSeconds / kSecondsPerDay));
  const int64_t year = civilFromDays(days).year;
  const double start = static_cast<double>(daysFromCivil(year, 1, 1)) * kSecondsPerDay;
  const double end = static_cast<double>(daysFromCivil(year + 1, 1, 1)) * kSecondsPerDay;
  return static_cast<double>(year) + (unixSeconds - start) / (end - start);
}

}  // namespace globe::sun
